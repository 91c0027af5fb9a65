/*! plugin integrator moment
Mitsuba's integrator that records, beside the image of the one integrator nested in it, the second moment of its samples (for variance estimates). Columba renders the nested integrator, whose image is Mitsuba's first moment, and warns, naming the line, that the second moment is not recorded. Mitsuba 3's render-test scenes wrap their integrators in it.
Mitsuba 3: exactly one nested integrator (Mitsuba takes several and records each), its image only: no second-moment channels.
*/
#include "integrators/moment_integrator.h"

#include "core/error.h"
#include "integrators/integrator.h"
#include "integrators/particle_tracer_integrator.h"

namespace columba {

std::shared_ptr<Object> makeMomentIntegrator(const Properties& props) {
  std::shared_ptr<Object> nested = props.child<Integrator>();
  std::shared_ptr<Object> tracer = props.child<ParticleTracerIntegrator>();
  if (!nested == !tracer)
    throw InputError(props.location, "'moment' takes exactly one nested integrator, whose image it renders");
  warn(props.location,
       "moment: the nested integrator's image is rendered; the second moment of its samples is not recorded");
  return nested ? nested : tracer;
}

}  // namespace columba
