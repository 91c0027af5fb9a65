#pragma once
// The cells of a row of an observer file (a table of sensitivities or of cone parameters): split
// at commas, tabs and spaces, empty cells dropped, as biologists' CSV and whitespace tables mix.
#include <sstream>
#include <string>
#include <vector>

namespace columba {

inline std::vector<std::string> tableCells(const std::string& line) {
  std::string text = line;
  for (char& c : text)
    if (c == ',' || c == '\t' || c == '\r') c = ' ';
  std::istringstream in(text);
  std::vector<std::string> cells;
  for (std::string cell; in >> cell;) cells.push_back(cell);
  return cells;
}

}  // namespace columba
