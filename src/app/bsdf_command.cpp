#include "app/bsdf_command.h"

#include <fmt/format.h>

#include <filesystem>

#include "bsdfs/barbule_measurement.h"
#include "plot/line_plot.h"
#include "plot/canvas.h"

namespace columba {

namespace {
struct BSDFOptions {
  BarbuleParameters params;
  float thetaDegrees = 45.0f, phiDegrees = 0.0f;
  int resolution = 256;
  std::string outputDir = ".";
};

Vec3 directionFromDegrees(float theta, float phi) {
  float t = degToRad(theta), p = degToRad(phi);
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

void runBSDF(const BSDFOptions& options) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(options.outputDir))
    throw std::runtime_error("output directory '" + options.outputDir + "' does not exist");
  BarbuleBSDF bsdf(options.params);
  fs::path dir(options.outputDir);

  Vec3 light = directionFromDegrees(options.thetaDegrees, options.phiDegrees);
  Image hemisphere = scatterometerImage(bsdf, light, options.resolution);
  writeEXR((dir / "bsdf_hemisphere.exr").string(), hemisphere);
  writePNG((dir / "bsdf_hemisphere.png").string(), hemisphere);

  // Spectra for light in the cross-section plane (across the barbules) at a few angles.
  const float angles[] = {0.0f, 20.0f, 40.0f, 60.0f};
  const Vec3 colours[] = {srgbColour(0.10f, 0.35f, 0.80f), srgbColour(0.10f, 0.60f, 0.30f),
                          srgbColour(0.85f, 0.55f, 0.05f), srgbColour(0.80f, 0.15f, 0.15f)};
  LinePlot plot;
  plot.title = fmt::format("Barbule lobe reflectance (height {:.2f} um, b {:.2f}, H {:.2f})", options.params.height,
                           options.params.b, options.params.H);
  plot.xLabel = "wavelength (nm)";
  plot.yLabel = "directional reflectance (R solid, TRT dashed)";
  plot.xMin = kLambdaMin;
  plot.xMax = kLambdaMax;
  float peak = 0.0f;
  std::vector<float> lambdas = visibleWavelengthGrid(5.0f);
  fmt::print("light angle  mean R   mean TRT  coverage  R peaks in 380-780 nm\n");
  for (int a = 0; a < 4; ++a) {
    Vec3 omegaI = directionFromDegrees(angles[a], 0.0f);
    LobeReflectance lr = lobeReflectance(bsdf, omegaI, lambdas);
    PlotSeries r{fmt::format("R {:g} deg", angles[a]), {}, colours[a]};
    PlotSeries t{fmt::format("TRT {:g} deg", angles[a]), {}, colours[a], true};
    double meanR = 0, meanT = 0;
    std::string peaks;
    for (size_t i = 0; i < lambdas.size(); ++i) {
      r.points.push_back(Vec2(lambdas[i], lr.reflection[i]));
      t.points.push_back(Vec2(lambdas[i], lr.trt[i]));
      peak = std::max(peak, std::max(lr.reflection[i], lr.trt[i]));
      bool localMax = i > 0 && i + 1 < lambdas.size() && lr.reflection[i] > lr.reflection[i - 1] &&
                      lr.reflection[i] >= lr.reflection[i + 1];
      if (localMax && lambdas[i] >= 380.0f && lambdas[i] <= 780.0f) peaks += fmt::format(" {:.0f}", lambdas[i]);
      meanR += lr.reflection[i] / lambdas.size();
      meanT += lr.trt[i] / lambdas.size();
    }
    fmt::print("{:8.0f}     {:7.4f}  {:7.4f}  {:7.3f}  {}\n", angles[a], meanR, meanT, bsdf.coverage(BSDFContext{}, omegaI),
               peaks);
    plot.series.push_back(std::move(r));
    plot.series.push_back(std::move(t));
  }
  plot.yMax = std::max(0.05f, peak * 1.1f);
  writePNG((dir / "bsdf_spectra.png").string(), renderLinePlot(plot, 1000, 640));
  fmt::print("wrote {}, {} and {}\n", (dir / "bsdf_hemisphere.exr").string(), (dir / "bsdf_hemisphere.png").string(),
             (dir / "bsdf_spectra.png").string());
}
}  // namespace

void addBSDFCommand(CLI::App& app) {
  auto o = std::make_shared<BSDFOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bsdf", "Plot the barbule BSDF: scatterometer hemisphere image (EXR + PNG) and lobe reflectance spectra (PNG)");
  cmd->add_option("--b", o->params.b, "Cross-section semi-axis along the vane normal")->check(CLI::PositiveNumber);
  cmd->add_option("--phi_0", o->params.phi0, "Start of the reflective arc (rad)");
  cmd->add_option("--phi_1", o->params.phi1, "End of the reflective arc (rad)");
  cmd->add_option("--mu", o->params.mu, "Tilt of the cross-section (rad)");
  cmd->add_option("--H", o->params.H, "Barbule spacing")->check(CLI::PositiveNumber);
  cmd->add_option("--height", o->params.height, "Keratin cortex thickness (um)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--theta", o->thetaDegrees, "Light polar angle from the vane normal (degrees)")->check(CLI::Range(0.0, 89.9));
  cmd->add_option("--phi", o->phiDegrees, "Light azimuth, 0 = across the barbules (degrees)");
  cmd->add_option("--res", o->resolution, "Hemisphere image size (pixels)")->check(CLI::Range(16, 4096));
  cmd->add_option("-o,--output", o->outputDir, "Output directory");
  cmd->callback([o] {
    if (!(o->params.phi1 > o->params.phi0)) throw std::runtime_error("--phi_1 must exceed --phi_0");
    runBSDF(*o);
  });
}

}  // namespace columba
