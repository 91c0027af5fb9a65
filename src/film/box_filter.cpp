/*! plugin rfilter box
The box filter: 1 on [−1/2, 1/2) pixel, half-open so that a sample on the border of two pixels counts for one.
Mitsuba 3: as Mitsuba 3's `box`.
*/
#include "film/box_filter.h"

namespace columba {

std::shared_ptr<Object> makeBoxFilter(const Properties&) { return std::make_shared<BoxFilter>(); }

}  // namespace columba
