#include "app/compare_command.h"

#include <fmt/format.h>

#include <cmath>
#include <cstring>

#include "app/jnd_comparison.h"
#include "io/image.h"
#include "io/output_directory.h"

namespace columba {

namespace {

struct CompareOptions {
  std::string a, b;
  double tolerance = 0.0;
  bool jnd = false;
  std::string observer, regionA, regionB, output;
};

int compareColourDistances(const CompareOptions& options) {
  if (!options.output.empty()) {
    if (checkOutputImagePath(options.output, true) != ImageFormat::EXR)
      throw std::runtime_error("-o '" + options.output +
                               "': the map of distances is written as an .exr (and its .png)");
    for (const std::string& out : {options.output, pngBesideMap(options.output)})
      refuseWritingOverAnInput(out, {options.a, options.b}, "the map of distances", "the image", "the comparison");
  }
  const EXRImageFile a = readEXRFile(options.a), b = readEXRFile(options.b);
  JndOptions jnd;
  jnd.observer = options.observer;
  jnd.output = options.output;
  if (!options.regionA.empty()) jnd.regionA = parsePixelRect(options.regionA, "--region");
  if (!options.regionB.empty()) jnd.regionB = parsePixelRect(options.regionB, "--region-b");
  if (jnd.regionB && !jnd.regionA)
    throw std::runtime_error("--region-b needs --region (the region of the first image)");
  if (jnd.regionA && !jnd.output.empty())
    throw std::runtime_error("-o writes the per-pixel map: it cannot be combined with --region");
  compareColours(a, b, options.a, options.b, jnd);
  return 0;
}

int compareImages(const CompareOptions& options) {
  if (options.jnd) return compareColourDistances(options);
  EXRImageFile a = readEXRFile(options.a), b = readEXRFile(options.b);
  if (a.image.width != b.image.width || a.image.height != b.image.height)
    throw std::runtime_error(fmt::format("'{}' is {} x {} pixels but '{}' is {} x {}", options.a, a.image.width,
                                         a.image.height, options.b, b.image.width, b.image.height));
  if (a.image.spectral.centres != b.image.spectral.centres)
    throw std::runtime_error(fmt::format("'{}' and '{}' have different spectral channels", options.a, options.b));
  if (a.image.cones.names != b.image.cones.names)
    throw std::runtime_error(fmt::format("'{}' and '{}' have different cone channels", options.a, options.b));
  size_t differing = 0, worst = 0;
  double largest = 0.0;
  enum class Part { RGB, Band, Cone } worstPart = Part::RGB;
  auto compare = [&](const std::vector<float>& x, const std::vector<float>& y, Part part) {
    for (size_t i = 0; i < x.size(); ++i) {
      if (std::memcmp(&x[i], &y[i], sizeof(float)) == 0) continue;
      ++differing;
      double d = std::isnan(x[i]) || std::isnan(y[i]) ? INFINITY : std::abs(double(x[i]) - double(y[i]));
      if (d >= largest) largest = d, worst = i, worstPart = part;
    }
  };
  compare(a.image.rgb, b.image.rgb, Part::RGB);
  compare(a.image.spectral.values, b.image.spectral.values, Part::Band);
  compare(a.image.cones.values, b.image.cones.values, Part::Cone);
  const size_t total = a.image.rgb.size() + a.image.spectral.values.size() + a.image.cones.values.size();
  if (differing == 0) {
    fmt::print("identical: all {} values of {} x {} pixels are bit for bit the same\n", total, a.image.width,
               a.image.height);
    return 0;
  }
  const size_t perPixel = worstPart == Part::Band   ? a.image.spectral.count()
                          : worstPart == Part::Cone ? a.image.cones.count()
                                                    : 3;
  const size_t pixel = worst / perPixel;
  const std::vector<float>& va = worstPart == Part::Band   ? a.image.spectral.values
                                 : worstPart == Part::Cone ? a.image.cones.values
                                                           : a.image.rgb;
  const std::vector<float>& vb = worstPart == Part::Band   ? b.image.spectral.values
                                 : worstPart == Part::Cone ? b.image.cones.values
                                                           : b.image.rgb;
  fmt::print(
      "{} of {} values differ; the largest difference is {:.9g} ({:.9g} against {:.9g}) at pixel ({}, {}), {} "
      "{}\n",
      differing, total, largest, va[worst], vb[worst], pixel % a.image.width, pixel / a.image.width,
      worstPart == Part::Band   ? "band"
      : worstPart == Part::Cone ? "cone channel"
                                : "channel",
      worst % perPixel);
  if (largest <= options.tolerance) {
    fmt::print("within the tolerance of {:g}\n", options.tolerance);
    return 0;
  }
  return 1;
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Compare two EXR images value by value (exit status 0: identical), or their colours as a bird or a human "
      "sees them (--jnd)");
  cmd->add_option("a", options->a, "An EXR image")->required();
  cmd->add_option("b", options->b, "Another EXR image of the same size")->required();
  cmd->add_option("--tolerance", options->tolerance,
                  "Largest absolute difference still accepted (default 0: bit-identical only)");
  cmd->add_flag(
      "--jnd", options->jnd,
      "Colour distances pixel by pixel or between regions: dS (JND) between the cone catches of renders whose "
      "film has a bird's observer; CIEDE2000 between the RGB of others (observer cie1931)");
  cmd->add_option("--observer", options->observer,
                  "With --jnd: a bird's observer whose receptor noise is used, or cie1931 (default: the one image A "
                  "records, else cie1931)");
  cmd->add_option(
      "--region", options->regionA,
      "With --jnd: X0,Y0,X1,Y1, compare the mean catches of these pixels (of A, and of B unless --region-b)");
  cmd->add_option("--region-b", options->regionB, "With --jnd and --region: X0,Y0,X1,Y1, B's region");
  cmd->add_option("-o,--output", options->output,
                  "With --jnd: write the per-pixel distance as an EXR (and its PNG beside it), made where missing");
  cmd->callback([options] {
    if (!options->jnd)
      for (const auto& [option, value] : {std::pair{"--observer", options->observer},
                                          {"--region", options->regionA},
                                          {"--region-b", options->regionB},
                                          {"-o", options->output}})
        if (!value.empty())
          throw CLI::ValidationError(option, "compares colours as a bird or a human sees them: add --jnd");
    int code = compareImages(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace columba
