#include "io/data_files.h"

#include <fmt/format.h>

#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace columba {

namespace {
// Writes `text` to `path` through a temporary file, so that a failed write never leaves half a file.
void replaceWithText(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw std::runtime_error("cannot write '" + path + "': " + ec.message());
  }
}
}  // namespace

void writeCSV(const std::string& path, const CsvTable& table) {
  std::string text;
  for (const std::string& comment : table.comments) text += "# " + comment + "\n";
  for (size_t c = 0; c < table.columns.size(); ++c) text += (c ? "," : "") + table.columns[c];
  text += "\n";
  for (const std::vector<double>& row : table.rows) {
    for (size_t c = 0; c < row.size(); ++c) text += fmt::format("{}{:.7g}", c ? "," : "", row[c]);
    text += "\n";
  }
  replaceWithText(path, text);
}

void writeJSON(const std::string& path, const nlohmann::json& record) { replaceWithText(path, record.dump(2) + "\n"); }

}  // namespace columba
