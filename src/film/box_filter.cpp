#include "film/box_filter.h"

namespace columba {

std::shared_ptr<Object> makeBoxFilter(const Properties&) { return std::make_shared<BoxFilter>(); }

}  // namespace columba
