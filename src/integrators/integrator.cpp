#include "integrators/integrator.h"

namespace columba {

void readMitsubaPassParameters(const Properties& props) {
  props.getInt("samples_per_pass", -1);
  if (props.getFloat("timeout", -1.0f) > 0.0f)
    warn(props.locationOf("timeout"), "timeout is ignored: Columba renders every sample (lower sample_count instead)");
}

}  // namespace columba
