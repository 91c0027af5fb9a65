#pragma once
// Text files saved by spreadsheet programs and Windows editors often start with a UTF-8 byte-order
// mark (EF BB BF), which is no part of their first line.
#include <istream>

namespace columba {

// Reads past a UTF-8 byte-order mark at the current position of `in`, if there is one.
void skipByteOrderMark(std::istream& in);

}  // namespace columba
