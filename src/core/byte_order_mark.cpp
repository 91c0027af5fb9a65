#include "core/byte_order_mark.h"

namespace columba {

void skipByteOrderMark(std::istream& in) {
  static const char kMark[] = "\xEF\xBB\xBF";
  const std::istream::pos_type start = in.tellg();
  char read[3] = {};
  if (in.read(read, 3) && read[0] == kMark[0] && read[1] == kMark[1] && read[2] == kMark[2]) return;
  in.clear();
  in.seekg(start);
}

}  // namespace columba
