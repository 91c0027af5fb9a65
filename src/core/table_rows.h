#pragma once
// The rows of a text table as biologists and spreadsheet programs write them (CSV, tab- or
// space-separated): a UTF-8 byte-order mark before the first line skipped, blank lines and comment
// lines (their first character besides white space '#') skipped, each row's line number kept for
// messages. The one reader of the spectra CSV files of a fit and of observer tables and definitions.
#include <istream>
#include <string>
#include <vector>

namespace columba {

class TableRows {
 public:
  // How a line splits into cells: at commas alone, each cell trimmed and empty cells kept (a CSV
  // file's fields); or at commas and white space, empty items dropped (listItems, number_text.h).
  enum class Separators { Commas, CommasOrWhiteSpace };

  // Reads `in` from its current position, past a byte-order mark there.
  TableRows(std::istream& in, Separators separators);
  // The next row's cells into `cells`; false at the end of the text.
  bool next(std::vector<std::string>& cells);
  // The number (from 1) of the line last read: the row `next` gave, or the last line at the end.
  int line() const { return line_; }

 private:
  std::istream& in_;
  Separators separators_;
  int line_ = 0;
};

}  // namespace columba
