#pragma once
// Renders a scene by light tracing (`ptracer`): as Mitsuba, width x height x spp light samples
// (the crop window's pixels), each splatting wherever its light reaches the film. Splats cross
// tiles, so the samples are cut into blocks of consecutive sample indices, a number that depends
// on the film and spp only; each block's sampler is restarted per sample from (sample index,
// seed), each block splats into a buffer of its own, and the blocks are summed in block order.
// The image is therefore bit-identical for any thread count. A bounded number of buffers (by
// memory, not threads) is reused round after round.
//
// Light tracing renders whole images: windows and sample ranges (parts and passes), adaptive
// sampling and spectral bins, which all work pixel by pixel, are refused (std::runtime_error).
#include "integrators/particle_tracer_integrator.h"
#include "render/renderer.h"

namespace columba {

Image renderLightPaths(const Scene& scene, const ParticleTracerIntegrator& tracer, const RenderSettings& settings,
                       RenderStats& stats);

}  // namespace columba
