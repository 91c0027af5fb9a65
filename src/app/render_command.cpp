#include "app/render_command.h"

#include <fmt/format.h>

#include <charconv>
#include <filesystem>

#include "builtin/default_scene.h"
#include "app/interruption.h"
#include "app/progress_reporter.h"
#include "builtin/builtin_plugins.h"
#include "render/renderer.h"
#include "samplers/sampler_parameters.h"
#include "scene/scene.h"

namespace columba {

namespace {

struct RenderOptions {
  std::string scenePath;
  std::string output;
  std::vector<std::string> defines;
  std::string spp, threads;  // checked by parseCount, so that every value gets the same message
  uint64_t seed = 0;
  bool spectral = false;  // radiance per wavelength bin in the EXR besides RGB
  std::string bins = "16";
};

Defines parseDefines(const std::vector<std::string>& items) {
  Defines defines;
  for (const std::string& item : items) {
    size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::runtime_error("-D expects name=value, got '" + item + "'");
    defines[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return defines;
}

// The EXR and PNG a render writes. -o names one of them; the other is written beside it, so the
// linear data and the preview always exist together.
struct OutputPair {
  std::filesystem::path exr, png;

  // From -o (or, without one, the scene's name in the working directory); throws before any work
  // for a name Columba cannot write.
  static OutputPair fromOption(const RenderOptions& options) {
    namespace fs = std::filesystem;
    fs::path given = options.output;
    if (given.empty())
      given = (options.scenePath.empty() ? std::string("default") : fs::path(options.scenePath).stem().string()) + ".exr";
    ImageFormat format = checkOutputImagePath(given.string());
    OutputPair pair{given, given};
    if (format == ImageFormat::EXR) pair.png.replace_extension(".png");
    else pair.exr.replace_extension(".exr");
    checkOutputImagePath(pair.exr.string());
    checkOutputImagePath(pair.png.string());
    return pair;
  }

  // Where an interrupted render goes, so that it never replaces a finished image: OUT.partial.exr.
  OutputPair partial() const {
    auto mark = [](std::filesystem::path p) {
      std::filesystem::path extension = p.extension();
      return p.replace_extension().concat(".partial").concat(extension.string());
    };
    return {mark(exr), mark(png)};
  }
};

// A whole number given for `option`, or 0 if it was not given.
int parseCount(const char* option, const std::string& text, int lowest, int highest) {
  if (text.empty()) return 0;
  long long value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::invalid_argument || end != text.data() + text.size())
    throw std::runtime_error(fmt::format("{} expects a whole number, not '{}'", option, text));
  if (ec != std::errc() || value < lowest || value > highest)
    throw std::runtime_error(fmt::format("{} must be between {} and {}, not {}", option, lowest, highest, text));
  return int(value);
}

std::string describeDefines(const Defines& defines) {
  std::string text;
  for (const auto& [name, value] : defines) text += (text.empty() ? "" : "\n") + name + "=" + value;
  return text;
}

int runRender(const RenderOptions& options) {
  const int sppOption = parseCount("--spp", options.spp, 1, kMaxSamplesPerPixel);
  const int threads = parseCount("--threads", options.threads, 1, 65536);
  const int bins = parseCount("--bins", options.bins, 1, 470);
  if (!options.scenePath.empty() && !std::filesystem::is_regular_file(options.scenePath))
    throw std::runtime_error("scene file '" + options.scenePath + "' does not exist or is not a regular file");
  const OutputPair outputs = OutputPair::fromOption(options);

  Defines defines = parseDefines(options.defines);
  ParsedScene parsed = options.scenePath.empty() ? loadDefaultScene(defines)
                                                 : loadSceneFile(options.scenePath, defines, builtinPlugins());
  SourceLocation source{options.scenePath.empty() ? "<default scene>" : options.scenePath, 0};
  for (const std::string& name : parsed.unusedDefines)
    fmt::print(stderr, "warning: -D {}={}: the scene uses no variable ${}, so it has no effect\n", name,
               defines.at(name), name);
  Scene scene(parsed, source);

  const Film& film = scene.sensor().film();
  int spp = sppOption > 0 ? sppOption : scene.sensor().sampler().sampleCount();
  fmt::print(stderr, "Rendering {} ({}x{}, {} spp, {} shapes, {} primitives)\n", source.file, film.width(),
             film.height(), spp, scene.shapeCount(), scene.primitiveCount());

  ProgressReporter progress("render");
  RenderSettings settings;
  settings.samplesPerPixel = spp;
  settings.seed = options.seed;
  settings.threads = threads;
  if (options.spectral) settings.spectralBins = bins;
  settings.onTileDone = [&](int done, int total) { progress.update(done, total); };
  // Kept until the image is written: a second Ctrl-C while writing exits at once.
  InterruptionGuard interruption;
  settings.cancel = &interruption.requested();
  RenderStats stats;
  Image image = renderImage(scene, settings, stats);
  progress.finish();

  ImageMetadata metadata = {{"Scene", source.file},
                            {"Defines", describeDefines(defines)},
                            {"Samples per pixel", std::to_string(spp)},
                            {"Seed", std::to_string(options.seed)},
                            {"Render time", fmt::format("{:.3f} s", stats.seconds)},
                            {"Status", stats.complete ? "complete" : "interrupted"}};
  if (options.spectral)
    metadata.emplace_back("Spectral channels", fmt::format("{} bins of {:g} nm over {:g}-{:g} nm: mean radiance per "
                                                           "nm over each bin (S0.<centre>nm)",
                                                           bins, (settings.spectralMax - settings.spectralMin) / bins,
                                                           settings.spectralMin, settings.spectralMax));
  const OutputPair written = stats.complete ? outputs : outputs.partial();
  writeEXRAndPNG(written.exr.string(), written.png.string(), image, metadata);
  std::string dropped = stats.nonFiniteSamples == 0
                            ? ""
                            : fmt::format(", {} non-finite samples dropped", stats.nonFiniteSamples);
  fmt::print("{} {}: {:.2f} s, {:.3f} M samples/s, {:.3f} M rays/s{} -> {}, {}\n",
             stats.complete ? "Rendered" : "Interrupted; wrote the partial image of", source.file, stats.seconds,
             stats.samples / stats.seconds * 1e-6, stats.rays / stats.seconds * 1e-6, dropped, written.exr.string(),
             written.png.string());
  return stats.complete ? 0 : 128 + interruption.signalNumber();
}
}  // namespace

void addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a Mitsuba-style scene file (or the built-in scene) to EXR + PNG");
  cmd->add_option("scene", options->scenePath, "Scene file (XML); none: the built-in default scene");
  cmd->add_option("-o,--output", options->output,
                  "Output image, .exr or .png: the other of the two is written beside it (default: SCENE.exr)");
  cmd->add_option("-D,--define", options->defines, "Set a scene parameter: -D name=value (repeatable)")
      ->allow_extra_args(false);  // one name=value per -D, so that a scene file may follow
  cmd->add_option("--spp", options->spp,
                  fmt::format("Samples per pixel, 1 to {} (default: the scene's sampler)", kMaxSamplesPerPixel));
  cmd->add_option("--threads", options->threads, "Worker threads (default: all cores)");
  cmd->add_option("--seed", options->seed, "Random seed; the same seed gives the same image");
  cmd->add_flag("--spectral", options->spectral,
                "Also write radiance per wavelength bin over 400-700 nm into the EXR (channels S0.<centre>nm)");
  cmd->add_option("--bins", options->bins, "Wavelength bins for --spectral, 1 to 470 (default 16)");
  cmd->callback([options] {
    int code = runRender(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace columba
