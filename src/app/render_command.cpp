#include "app/render_command.h"

#include <fmt/format.h>

#include <csignal>
#include <filesystem>

#include "app/default_scene.h"
#include "app/progress_reporter.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace columba {

namespace {
std::atomic<bool> interrupted{false};
extern "C" void onInterrupt(int) { interrupted = true; }

struct RenderOptions {
  std::string scenePath;
  std::string output;
  std::vector<std::string> defines;
  int spp = 0;
  int threads = 0;
  uint64_t seed = 0;
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

int runRender(const RenderOptions& options) {
  Defines defines = parseDefines(options.defines);
  ParsedScene parsed = options.scenePath.empty() ? loadDefaultScene(defines)
                                                 : loadSceneFile(options.scenePath, defines, PluginRegistry::builtin());
  SourceLocation source{options.scenePath.empty() ? "<default scene>" : options.scenePath, 0};
  Scene scene(parsed, source);

  std::filesystem::path exrPath = options.output;
  if (exrPath.empty())
    exrPath = (options.scenePath.empty() ? std::string("default") : std::filesystem::path(options.scenePath).stem().string()) + ".exr";
  if (exrPath.extension() != ".exr") exrPath += ".exr";
  std::filesystem::path pngPath = exrPath;
  pngPath.replace_extension(".png");
  if (exrPath.has_parent_path() && !std::filesystem::is_directory(exrPath.parent_path()))
    throw std::runtime_error("output directory '" + exrPath.parent_path().string() + "' does not exist");

  const Film& film = scene.sensor().film();
  int spp = options.spp > 0 ? options.spp : scene.sensor().sampler().sampleCount();
  fmt::print(stderr, "Rendering {} ({}x{}, {} spp, {} shapes, {} primitives)\n", source.file, film.width(),
             film.height(), spp, scene.shapeCount(), scene.primitiveCount());

  ProgressReporter progress("render");
  RenderSettings settings;
  settings.samplesPerPixel = options.spp;
  settings.seed = options.seed;
  settings.threads = options.threads;
  settings.cancel = &interrupted;
  settings.onTileDone = [&](int done, int total) { progress.update(done, total); };
  auto previousHandler = std::signal(SIGINT, onInterrupt);
  RenderStats stats;
  Image image = renderImage(scene, settings, stats);
  std::signal(SIGINT, previousHandler);
  progress.finish();

  writeEXR(exrPath.string(), image);
  writePNG(pngPath.string(), image);
  fmt::print("{} {}: {:.2f} s, {:.3f} M samples/s, {:.3f} M rays/s -> {}, {}\n",
             stats.complete ? "Rendered" : "Interrupted; wrote the partial image of", source.file, stats.seconds,
             stats.samples / stats.seconds * 1e-6, stats.rays / stats.seconds * 1e-6, exrPath.string(), pngPath.string());
  return stats.complete ? 0 : 130;
}
}  // namespace

void addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a Mitsuba-style scene file (or the built-in scene) to EXR + PNG");
  cmd->add_option("scene", options->scenePath, "Scene file (XML); none: the built-in default scene")->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options->output, "Output EXR path; a PNG is written beside it");
  cmd->add_option("-D,--define", options->defines, "Set a scene parameter: -D name=value (repeatable)");
  cmd->add_option("--spp", options->spp, "Samples per pixel (default: the scene's sampler)")->check(CLI::PositiveNumber);
  cmd->add_option("--threads", options->threads, "Worker threads (default: all cores)")->check(CLI::PositiveNumber);
  cmd->add_option("--seed", options->seed, "Random seed; the same seed gives the same image");
  cmd->callback([options] {
    int code = runRender(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace columba
