#pragma once
// The data files the measurement commands write beside their plots: CSV tables with their units
// in '#' comment lines, and JSON records of a run (nlohmann::json).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace columba {

struct CsvTable {
  std::vector<std::string> comments;  // written first, each after "# " (units, parameters)
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

// Written to a temporary file renamed into place; throws std::runtime_error naming the path.
void writeCSV(const std::string& path, const CsvTable& table);
void writeJSON(const std::string& path, const nlohmann::json& record);

}  // namespace columba
