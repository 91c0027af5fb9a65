/*! plugin integrator volpath volpathmis
Mitsuba's volumetric path tracers, for scenes without participating media: there a volumetric path tracer follows the paths of the plain one, so both render what `path` renders with the same parameters (its default `strategy` and `emitter_candidates`), bit for bit. A scene with a medium is refused where the `<medium>` element is, naming its file and line, as participating media are not supported yet.
Mitsuba 3: the same parameters and defaults; media are refused; `timeout` does not stop the render.
uses: passes
| parameter | type | default | meaning | Mitsuba 3 |
| max_depth | integer | -1 | the longest path, in segments; -1 is unlimited, 1 shows the emitters seen directly only; below -1 is an error | same |
| rr_depth | integer | 5 | the depth from which Russian roulette ends paths (with probability 1 − min(throughput, 0.95)); at least 1 | same |
| hide_emitters | boolean | false | emitters seen directly by the camera are black | same |
*/
#include "integrators/volpath_integrator.h"

#include "integrators/path_integrator.h"

namespace columba {

std::shared_ptr<Object> makeVolumetricPathIntegrator(const Properties& props) {
  return makePathIntegratorWith(props, PathIntegrator::Strategy::MIS, PathIntegrator::kAutomatic);
}

}  // namespace columba
