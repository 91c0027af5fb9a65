#include "core/table_rows.h"

#include <sstream>

#include "core/byte_order_mark.h"
#include "core/number_text.h"

namespace columba {

namespace {
// As std::getline splits at commas: a comma that ends the line opens no empty last field.
std::vector<std::string> commaFields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(trimmed(field));
  return fields;
}
}  // namespace

TableRows::TableRows(std::istream& in, Separators separators) : in_(in), separators_(separators) {
  skipByteOrderMark(in_);
}

bool TableRows::next(std::vector<std::string>& cells) {
  for (std::string text; std::getline(in_, text);) {
    ++line_;
    const size_t first = text.find_first_not_of(" \t\r\n\f\v");
    if (first == std::string::npos || text[first] == '#') continue;
    cells = separators_ == Separators::Commas ? commaFields(text) : listItems(text);
    return true;
  }
  return false;
}

}  // namespace columba
