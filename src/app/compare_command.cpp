#include "app/compare_command.h"

#include <fmt/format.h>

#include <cmath>
#include <cstring>

#include "io/image.h"

namespace columba {

namespace {

struct CompareOptions {
  std::string a, b;
  double tolerance = 0.0;
};

int compareImages(const CompareOptions& options) {
  EXRImageFile a = readEXRFile(options.a), b = readEXRFile(options.b);
  if (a.image.width != b.image.width || a.image.height != b.image.height)
    throw std::runtime_error(fmt::format("'{}' is {} x {} pixels but '{}' is {} x {}", options.a, a.image.width,
                                         a.image.height, options.b, b.image.width, b.image.height));
  if (a.image.spectral.centres != b.image.spectral.centres)
    throw std::runtime_error(fmt::format("'{}' and '{}' have different spectral channels", options.a, options.b));
  size_t differing = 0, worst = 0;
  double largest = 0.0;
  bool worstSpectral = false;
  auto compare = [&](const std::vector<float>& x, const std::vector<float>& y, bool spectral) {
    for (size_t i = 0; i < x.size(); ++i) {
      if (std::memcmp(&x[i], &y[i], sizeof(float)) == 0) continue;
      ++differing;
      double d = std::isnan(x[i]) || std::isnan(y[i]) ? INFINITY : std::abs(double(x[i]) - double(y[i]));
      if (d >= largest) largest = d, worst = i, worstSpectral = spectral;
    }
  };
  compare(a.image.rgb, b.image.rgb, false);
  compare(a.image.spectral.values, b.image.spectral.values, true);
  const size_t total = a.image.rgb.size() + a.image.spectral.values.size();
  if (differing == 0) {
    fmt::print("identical: all {} values of {} x {} pixels are bit for bit the same\n", total, a.image.width,
               a.image.height);
    return 0;
  }
  const size_t perPixel = worstSpectral ? a.image.spectral.count() : 3;
  const size_t pixel = worst / perPixel;
  const std::vector<float>& va = worstSpectral ? a.image.spectral.values : a.image.rgb;
  const std::vector<float>& vb = worstSpectral ? b.image.spectral.values : b.image.rgb;
  fmt::print(
      "{} of {} values differ; the largest difference is {:.9g} ({:.9g} against {:.9g}) at pixel ({}, {}), {} "
      "{}\n",
      differing, total, largest, va[worst], vb[worst], pixel % a.image.width, pixel / a.image.width,
      worstSpectral ? "band" : "channel", worst % perPixel);
  if (largest <= options.tolerance) {
    fmt::print("within the tolerance of {:g}\n", options.tolerance);
    return 0;
  }
  return 1;
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand("compare", "Compare two EXR images value by value (exit status 0: identical)");
  cmd->add_option("a", options->a, "An EXR image")->required();
  cmd->add_option("b", options->b, "Another EXR image of the same size")->required();
  cmd->add_option("--tolerance", options->tolerance,
                  "Largest absolute difference still accepted (default 0: bit-identical only)");
  cmd->callback([options] {
    int code = compareImages(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace columba
