#include "app/render_command.h"

#include <fmt/format.h>

#include <charconv>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>

#include "app/interruption.h"
#include "app/progress_reporter.h"
#include "builtin/builtin_plugins.h"
#include "builtin/default_scene.h"
#include "builtin/default_scene_xml.h"
#include "core/version.h"
#include "distribute/manifest.h"
#include "distribute/pieces.h"
#include "io/image.h"
#include "render/renderer.h"
#include "samplers/sampler_parameters.h"
#include "scene/scene.h"

namespace columba {

namespace {

struct RenderOptions {
  SceneOptions scene;
  std::string output;
  std::string threads;
  std::string frame;         // --frame I: only frame I of the sweep
  std::string part, pass;    // --part K/N, --pass K/N
  std::string manifest;      // --manifest FILE
  bool adaptive = false;     // --adaptive
  double targetError = 0.0;  // --target-error E (0: none)
};

Defines parseDefines(const std::vector<std::string>& items) {
  Defines defines;
  for (const std::string& item : items) {
    size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0) throw std::runtime_error("-D expects name=value, got '" + item + "'");
    defines[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return defines;
}

// The EXR and PNG a render writes. -o names one of them; the other is written beside it, so the
// linear data and the preview always exist together.
struct OutputPair {
  std::filesystem::path exr, png;

  // Throws before any work for a name Columba cannot write.
  static OutputPair fromPath(const std::string& path) {
    std::filesystem::path given = path;
    ImageFormat format = checkOutputImagePath(given.string());
    OutputPair pair{given, given};
    if (format == ImageFormat::EXR)
      pair.png.replace_extension(".png");
    else
      pair.exr.replace_extension(".exr");
    checkOutputImagePath(pair.exr.string());
    checkOutputImagePath(pair.png.string());
    return pair;
  }

  // Where an interrupted render goes, so that it never replaces a finished image: OUT.partial.exr.
  OutputPair partial() const { return {partialFileName(exr.string()), partialFileName(png.string())}; }
};

std::string defaultOutput(const std::string& scenePath) {
  return (scenePath.empty() ? std::string("default") : std::filesystem::path(scenePath).stem().string()) + ".exr";
}

std::string readSceneText(const std::string& scenePath) {
  if (scenePath.empty()) return kDefaultSceneXML;
  std::ifstream in(scenePath, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The manifest of a local sweep: written with every frame pending, then as frames finish.
std::string defaultManifestPath(const RenderOptions& options) {
  namespace fs = std::filesystem;
  if (!options.scene.framesPattern.empty()) {
    fs::path dir = fs::path(options.scene.framesPattern).parent_path();
    return (dir / "manifest.json").string();
  }
  fs::path out = options.output.empty() ? fs::path(defaultOutput(options.scene.scenePath)) : fs::path(options.output);
  return out.replace_extension().string() + ".manifest.json";
}

// A sweep replaces only a local sweep's manifest: not a Slurm job's (whose merge job and reruns
// read it), nor a file that is no manifest (a default name such as ./manifest.json may be taken).
void refuseReplacingManifest(const std::string& path) {
  if (!std::filesystem::exists(path)) return;
  Manifest old;
  try {
    old = readManifest(path);
  } catch (const std::exception& e) {
    throw std::runtime_error(
        fmt::format("the sweep's manifest would replace '{}', which is no Columba manifest ({}): "
                    "give --manifest FILE, or remove it",
                    path, e.what()));
  }
  if (!old.renderScript.empty() || !old.submissions.empty())
    throw std::runtime_error(fmt::format(
        "the sweep's manifest would replace '{}', the manifest of a Slurm job (columba slurm): give --manifest FILE, "
        "or put the frames elsewhere",
        path));
}

std::string frameLabel(const SweepFrame& frame) {
  std::string label;
  for (const auto& [name, value] : frame.values) label += (label.empty() ? "" : " ") + name + "=" + value;
  return label;
}

int runRender(const RenderOptions& options) {
  const int sppOption = parseCount("--spp", options.scene.spp, 1, kMaxSamplesPerPixel);
  const int threads = parseCount("--threads", options.threads, 1, 65536);
  setImageWriterThreads(threads);
  const int bins = parseCount("--bins", options.scene.bins, 1, 470);
  std::optional<PieceIndex> part, pass;
  if (!options.part.empty()) part = parsePieceIndex("--part", options.part, 65536);
  if (!options.pass.empty()) pass = parsePieceIndex("--pass", options.pass, kMaxSamplesPerPixel);
  const FramePlan plan = planFrames(options.scene, options.output);
  const int frameCount = int(plan.frames.size());
  std::vector<int> selected;
  if (!options.frame.empty()) {
    int f = parseCount("--frame", options.frame, 0, 1 << 30);
    if (f >= frameCount)
      throw std::runtime_error(fmt::format("--frame {}: the sweep has {} frame{} (0 to {})", f, frameCount,
                                           frameCount == 1 ? "" : "s", frameCount - 1));
    selected.push_back(f);
  } else {
    for (int f = 0; f < frameCount; ++f) selected.push_back(f);
  }
  const bool piece = part || pass;
  const double targetError = options.targetError;
  if (targetError != 0.0 && !(targetError > 0.0 && targetError < 1.0))
    throw std::runtime_error(fmt::format(
        "--target-error {}: give the relative RMSE to reach, a number between 0 and 1 (e.g. 0.02)", targetError));
  const bool adaptive = options.adaptive || targetError > 0.0;
  if (adaptive && piece)
    throw std::runtime_error(
        "--adaptive and --target-error render whole images: they cannot be combined with --part "
        "or --pass");
  // Every output is checked before the first frame is rendered.
  std::vector<OutputPair> outputs;
  for (const std::string& file : plan.files) {
    outputs.push_back(OutputPair::fromPath(file));
    if (piece) checkOutputImagePath(pieceFileName(file, part, pass));
  }

  // A sweep rendered here in full keeps a manifest; the pieces of a split render leave that to
  // whoever split it (`columba slurm`), since many of them run at once.
  const bool sweeping = !plan.axes.empty();
  const bool keepManifest = (sweeping || !options.manifest.empty()) && options.frame.empty() && !piece;
  const std::string manifestPath = options.manifest.empty() ? defaultManifestPath(options) : options.manifest;
  Manifest manifest;
  if (keepManifest) {
    refuseReplacingManifest(manifestPath);
    manifest.columbaVersion = kColumbaVersion;
    manifest.scene = options.scene.scenePath.empty() ? "<default scene>" : options.scene.scenePath;
    manifest.sceneHash = plan.sceneHash;
    manifest.defines = plan.defines;
    manifest.sweeps = plan.axes;
    manifest.spp = sppOption;
    manifest.seed = options.scene.seed;
    for (int f = 0; f < frameCount; ++f) {
      ManifestFrame frame;
      frame.frame = f;
      frame.defines = plan.frameDefines(f);
      frame.seed = options.scene.seed;
      frame.spp = sppOption;
      frame.output = outputs[size_t(f)].exr.string();
      manifest.frames.push_back(frame);
    }
    writeManifest(manifestPath, manifest);
  }

  // Kept until the last image is written. Stops are deferred from the start of each frame's render
  // to its image on disk: a signal while a scene loads ends the process at once, and a second
  // Ctrl-C while writing exits at once.
  InterruptionGuard interruption(
      "\nStopping: finishing the current samples and saving the partial image "
      "(interrupt again to quit at once)\n");
  OverallProgress overall;
  overall.total = int(selected.size());
  overall.start = std::chrono::steady_clock::now();
  std::set<std::string> warned;
  double renderSeconds = 0.0;
  for (size_t i = 0; i < selected.size(); ++i) {
    const int f = selected[i];
    const Defines defines = plan.frameDefines(f);
    const std::string label = frameLabel(plan.frames[size_t(f)]);
    if (sweeping) fmt::print(stderr, "Frame {} ({} of {}): {}\n", f, i + 1, selected.size(), label);
    ParsedScene parsed = loadFrameScene(options.scene, defines);
    const SourceLocation source = frameSceneSource(options.scene);
    for (const std::string& name : parsed.unusedDefines)
      if (warned.insert(name).second)
        fmt::print(stderr, "warning: -D {}={}: the scene uses no variable ${}, so it has no effect\n", name,
                   defines.at(name), name);
    Scene scene(parsed, source);

    const Film& film = scene.sensor().film();
    int spp = sppOption > 0 ? sppOption : scene.sensor().sampler().sampleCount();
    RenderSettings settings;
    settings.samplesPerPixel = spp;
    settings.seed = options.scene.seed;
    settings.threads = threads;
    settings.adaptive = adaptive;
    settings.targetError = targetError;
    if (options.scene.spectral) settings.spectralBins = bins;
    PieceInfo info;
    info.scene = source.file;
    info.sceneHash = plan.sceneHash;
    info.defines = describeDefines(defines);
    info.seed = options.scene.seed;
    info.spp = spp;
    // A split render's frame is the film's crop window (the whole film unless cropped): the pieces'
    // windows are relative to it, and merged they make the image a render in one piece makes.
    const PixelRect& crop = film.crop();
    info.frameWidth = crop.width();
    info.frameHeight = crop.height();
    if (options.scene.spectral)
      info.spectral = fmt::format(
          "{} bins of {:g} nm over {:g}-{:g} nm: mean radiance per nm over each bin "
          "(S0.<centre>nm)",
          bins, (settings.spectralMax - settings.spectralMin) / bins, settings.spectralMin, settings.spectralMax);
    std::string pieceText;
    if (part) {
      // Bands of rows of about equal cost, from a pilot every part computes alike.
      info.part = part;
      if (part->count == 1) {
        info.partBounds = {0, crop.height()};
      } else {
        const std::vector<uint64_t> rowCosts = estimateRowCosts(scene, settings);
        info.partBounds = balancedRowBands({rowCosts.begin() + crop.y0, rowCosts.begin() + crop.y1}, part->count);
      }
      const PixelRect window = partWindow(info.partBounds, part->index, crop.width());
      settings.window = {crop.x0 + window.x0, crop.y0 + window.y0, crop.x0 + window.x1, crop.y0 + window.y1};
      pieceText = fmt::format(", part {} (rows {}-{})", part->str(), window.y0, window.y1 - 1);
    }
    if (pass) {
      info.pass = pass;
      std::tie(info.sampleBegin, info.sampleEnd) = passSamples(*pass, spp);
      settings.sampleBegin = info.sampleBegin;
      settings.sampleEnd = info.sampleEnd;
      pieceText += fmt::format(", pass {} (samples {}:{})", pass->str(), info.sampleBegin, info.sampleEnd);
    }
    const std::string cropText =
        crop.width() == film.width() && crop.height() == film.height()
            ? ""
            : fmt::format(", cropped to {}x{} at ({}, {})", crop.width(), crop.height(), crop.x0, crop.y0);
    fmt::print(stderr, "Rendering {} ({}x{}{}, {} spp{}, {} shapes, {} primitives)\n", source.file, film.width(),
               film.height(), cropText, spp, pieceText, scene.shapeCount(), scene.primitiveCount());

    overall.done = int(i);
    ProgressReporter progress(sweeping ? fmt::format("frame {}/{}", i + 1, selected.size()) : "render",
                              sweeping ? &overall : nullptr);
    settings.onTileDone = [&](int done, int total) { progress.update(done, total); };
    settings.cancel = &interruption.requested();
    interruption.deferStops();
    RenderStats stats;
    Image image = renderImage(scene, settings, stats);
    progress.finish();
    renderSeconds += stats.seconds;

    info.complete = stats.complete;
    info.seconds = stats.seconds;
    const ImageMetadata metadata = pieceMetadata(info);
    const OutputPair& output = outputs[size_t(f)];
    std::string written;
    if (piece) {
      const std::string file = pieceFileName(output.exr.string(), part, pass);
      written = stats.complete ? file : partialFileName(file);
      const PixelRect window = settings.window.empty() ? crop : settings.window;
      writeEXRWindow(written, image,
                     {window.x0 - crop.x0, window.y0 - crop.y0, window.x1 - crop.x0, window.y1 - crop.y0}, crop.width(),
                     crop.height(), metadata);
    } else {
      const OutputPair pair = stats.complete ? output : output.partial();
      writeEXRAndPNG(pair.exr.string(), pair.png.string(), image, metadata);
      written = pair.exr.string() + ", " + pair.png.string();
    }
    std::string dropped =
        stats.nonFiniteSamples == 0 ? "" : fmt::format(", {} non-finite samples dropped", stats.nonFiniteSamples);
    fmt::print("{} {}{}: {:.2f} s, {:.3f} M samples/s, {:.3f} M rays/s{} -> {}\n",
               stats.complete ? "Rendered" : "Interrupted; wrote the partial image of", source.file,
               sweeping ? " (" + label + ")" : "", stats.seconds, stats.samples / stats.seconds * 1e-6,
               stats.rays / stats.seconds * 1e-6, dropped, written);
    if (adaptive && stats.complete)
      fmt::print(
          "Adaptive sampling: {} pilot samples per pixel, then {} to {} ({:.1f} on average); predicted relative "
          "RMSE {:.4f}\n",
          stats.pilotSamples, stats.fewestSamples, stats.mostSamples,
          double(stats.samples) / (double(film.width()) * film.height()), stats.predictedRelativeError);
    std::fflush(stdout);
    if (keepManifest) {
      ManifestFrame& frame = manifest.frames[size_t(f)];
      frame.status = stats.complete ? "done" : "interrupted";
      frame.spp = spp;
      frame.seconds = stats.seconds;
      if (!stats.complete) frame.output = output.partial().exr.string();
      writeManifest(manifestPath, manifest);
    }
    if (!stats.complete) return 128 + interruption.signalNumber();
    interruption.stopAtOnce();
    // A signal while the finished frame was written: the next frame is not begun.
    if (interruption.requested()) return 128 + interruption.signalNumber();
    if (sweeping && selected.size() > 1) {
      overall.done = int(i) + 1;
      fmt::print(stderr, "Frame {} done in {}; {} of {} frames, {}\n", f, formatDuration(stats.seconds), i + 1,
                 selected.size(), overall.eta(0.0));
    }
  }
  if (sweeping && selected.size() > 1)
    fmt::print("Rendered {} frames: {:.2f} s rendering, {:.2f} s in all{}\n", selected.size(), renderSeconds,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - overall.start).count(),
               keepManifest ? " (manifest: " + manifestPath + ")" : "");
  return 0;
}
}  // namespace

ParsedScene loadFrameScene(const SceneOptions& options, const Defines& defines) {
  return options.scenePath.empty() ? loadDefaultScene(defines)
                                   : loadSceneFile(options.scenePath, defines, builtinPlugins());
}

SourceLocation frameSceneSource(const SceneOptions& options) {
  return {options.scenePath.empty() ? "<default scene>" : options.scenePath, 0};
}

std::map<std::string, std::string> FramePlan::frameDefines(int f) const {
  std::map<std::string, std::string> all = defines;
  for (const auto& [name, value] : frames[size_t(f)].values) all[name] = value;
  return all;
}

std::string describeDefines(const std::map<std::string, std::string>& defines) {
  std::string text;
  for (const auto& [name, value] : defines) text += (text.empty() ? "" : "\n") + name + "=" + value;
  return text;
}

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

FramePlan planFrames(const SceneOptions& options, const std::string& output) {
  if (!options.scenePath.empty() && !std::filesystem::is_regular_file(options.scenePath))
    throw std::runtime_error("scene file '" + options.scenePath + "' does not exist or is not a regular file");
  FramePlan plan;
  plan.defines = parseDefines(options.defines);
  for (const std::string& spec : options.sweeps) {
    plan.axes.push_back(parseSweep(spec));
    if (plan.defines.count(plan.axes.back().name))
      throw std::runtime_error(
          fmt::format("-D {0}=... and --sweep {0}=... both set ${0}; give one of them", plan.axes.back().name));
  }
  plan.frames = expandSweeps(plan.axes);
  plan.files =
      frameFiles(output.empty() ? defaultOutput(options.scenePath) : output, options.framesPattern, plan.frames);
  plan.sceneHash = textHash(readSceneText(options.scenePath));
  return plan;
}

void addSceneOptions(CLI::App* cmd, SceneOptions& options) {
  cmd->add_option("scene", options.scenePath, "Scene file (XML); none: the built-in default scene");
  cmd->add_option("-D,--define", options.defines, "Set a scene parameter: -D name=value (repeatable)")
      ->allow_extra_args(false);  // one name=value per -D, so that a scene file may follow
  cmd->add_option("--spp", options.spp,
                  fmt::format("Samples per pixel, 1 to {} (default: the scene's sampler)", kMaxSamplesPerPixel));
  cmd->add_option("--seed", options.seed, "Random seed; the same seed gives the same image");
  cmd->add_flag("--spectral", options.spectral,
                "Also write radiance per wavelength bin over 400-700 nm into the EXR (channels S0.<centre>nm)");
  cmd->add_option("--bins", options.bins, "Wavelength bins for --spectral, 1 to 470 (default 16)");
  cmd->add_option("--sweep", options.sweeps,
                  "Render one frame per value of a scene variable: NAME=START:STOP:STEP (STOP included) or "
                  "NAME=v1,v2,...; several --sweep form a grid (the first varies slowest)")
      ->allow_extra_args(false);
  cmd->add_option("--frames", options.framesPattern,
                  "The frames' file names: %d or %03d is the frame index, {NAME} a swept value, {NAME:03} the "
                  "value formatted (default: OUT_NAME=VALUE.exr from -o)");
}

void addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd =
      app.add_subcommand("render", "Render a Mitsuba-style scene file (or the built-in scene) to EXR + PNG");
  addSceneOptions(cmd, options->scene);
  cmd->add_option("-o,--output", options->output,
                  "Output image, .exr or .png: the other of the two is written beside it (default: SCENE.exr)");
  cmd->add_option("--threads", options->threads, "Worker threads (default: all cores)");
  cmd->add_option("--frame", options->frame, "Render only this frame of the sweep (0-based, as in the manifest)");
  cmd->add_option("--part", options->part,
                  "Render only the K-th of N bands of rows (of about equal cost) to OUT.partKofN.exr, for "
                  "`columba merge`: K/N");
  cmd->add_option("--pass", options->pass,
                  "Render only the K-th of N ranges of every pixel's sample indices to OUT.passKofN.exr, for "
                  "`columba merge`: K/N");
  cmd->add_flag("--adaptive", options->adaptive,
                "Adaptive sampling: --spp becomes the mean budget per pixel; after a pilot of a quarter of it (2 to "
                "16), each pixel gets samples in proportion to how much its neighbours' samples vary");
  cmd->add_option("--target-error", options->targetError,
                  "Adaptive sampling that stops at the budget its plan predicts for this relative RMSE (e.g. 0.02), "
                  "at most --spp per pixel on average");
  cmd->add_option("--manifest", options->manifest,
                  "The sweep's manifest, JSON (default: OUT.manifest.json, or manifest.json beside --frames)");
  cmd->callback([options] {
    int code = runRender(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace columba
