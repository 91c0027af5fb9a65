/*! parameters passes
| parameter | type | default | meaning | Mitsuba 3 |
| samples_per_pass | integer | -1 | accepted and ignored: passes only split the same samples, so the image would not change | splits the render into passes |
| timeout | float | -1 | accepted; a positive value warns, naming the line, and every sample is still rendered | stops the render after that many seconds |
*/
#include "integrators/integrator.h"

namespace columba {

void readMitsubaPassParameters(const Properties& props) {
  props.getInt("samples_per_pass", -1);
  if (props.getFloat("timeout", -1.0f) > 0.0f)
    warn(props.locationOf("timeout"), "timeout is ignored: Columba renders every sample (lower sample_count instead)");
}

}  // namespace columba
