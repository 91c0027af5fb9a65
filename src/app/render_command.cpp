#include "app/render_command.h"

#include <fmt/format.h>

#include <charconv>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>
#include <tuple>

#include "app/cli_checks.h"
#include "app/interruption.h"
#include "app/progress_reporter.h"
#include "app/scene_options.h"
#include "core/version.h"
#include "distribute/manifest.h"
#include "distribute/pieces.h"
#include "io/image.h"
#include "io/output_directory.h"
#include "render/renderer.h"
#include "samplers/sampler_parameters.h"
#include "scene/scene.h"
#include "vision/observer_response.h"

namespace columba {

namespace {

struct RenderOptions {
  SceneOptions scene;
  std::string output;
  std::string threads;
  std::string frame;              // --frame I: only frame I of the sweep
  std::string part, pass;         // --part K/N, --pass K/N
  std::string manifest;           // --manifest FILE
  bool adaptive = false;          // --adaptive
  double targetError = 0.0;       // --target-error E (0: none)
  float exposure = 0.0f;          // --exposure EV: the PNG's only
  std::string toneMap = "clamp";  // --tonemap: the PNG's only
};

// The EXR and PNG a render writes. -o names one of them; the other is written beside it, so the
// linear data and the preview always exist together.
struct OutputPair {
  std::filesystem::path exr, png;

  // Throws before any work for a name Columba cannot write. Its directory may be missing if it
  // can be made (makeDirectory makes it).
  static OutputPair fromPath(const std::string& path) {
    std::filesystem::path given = path;
    ImageFormat format = checkOutputImagePath(given.string(), true);
    OutputPair pair{given, given};
    if (format == ImageFormat::EXR)
      pair.png.replace_extension(".png");
    else
      pair.exr.replace_extension(".exr");
    checkOutputImagePath(pair.exr.string(), true);
    checkOutputImagePath(pair.png.string(), true);
    return pair;
  }

  void makeDirectory() const { makeOutputDirectory(exr.string(), directoryOf(exr.string())); }

  // Where an interrupted render goes, so that it never replaces a finished image: OUT.partial.exr.
  OutputPair partial() const { return {partialFileName(exr.string()), partialFileName(png.string())}; }
};

// The manifest of a local sweep: written with every frame pending, then as frames finish.
std::string defaultManifestPath(const RenderOptions& options) {
  namespace fs = std::filesystem;
  if (!options.scene.framesPattern.empty()) {
    // In the frames' directory, or where their directories part (before the first with a {NAME}
    // or %03d in its name).
    fs::path dir;
    for (const fs::path& part : fs::path(options.scene.framesPattern).parent_path()) {
      if (part.string().find_first_of("{%") != std::string::npos) break;
      dir /= part;
    }
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

// What a render does, decided before its first frame: every option checked, every output named.
struct RenderPlan {
  RenderSettings settings;  // from the options; each frame adds its sample count and piece
  bool spectral = false;
  float exposure = 0.0f;  // of the PNG, stops
  ToneMap toneMap = ToneMap::Clamp;
  std::optional<PieceIndex> part, pass;
  FramePlan frames;
  std::vector<int> selected;        // the frames to render (all, or --frame's)
  std::vector<OutputPair> outputs;  // every frame's
  bool sweeping = false;
  // A sweep rendered here in full keeps a manifest; the pieces of a split render leave that to
  // whoever split it (`columba slurm`), since many of them run at once.
  bool keepManifest = false;
  std::string manifestPath;

  bool piece() const { return part || pass; }
};

std::vector<int> selectedFrames(const std::string& frameOption, int frameCount) {
  std::vector<int> selected;
  if (!frameOption.empty()) {
    int f = parseCount("--frame", frameOption, 0, 1 << 30);
    if (f >= frameCount)
      throw std::runtime_error(fmt::format("--frame {}: the sweep has {} frame{} (0 to {})", f, frameCount,
                                           frameCount == 1 ? "" : "s", frameCount - 1));
    selected.push_back(f);
  } else {
    for (int f = 0; f < frameCount; ++f) selected.push_back(f);
  }
  return selected;
}

RenderPlan planRender(const RenderOptions& options) {
  RenderPlan plan;
  RenderSettings& settings = plan.settings;
  settings.samplesPerPixel = parseCount("--spp", options.scene.spp, 1, kMaxSamplesPerPixel);
  settings.seed = options.scene.seed;
  settings.threads = parseCount("--threads", options.threads, 1, kMaxRenderThreads);
  const int bins = parseCount("--bins", options.scene.bins, 1, kMaxSpectralBins);
  plan.spectral = options.scene.spectral;
  plan.exposure = options.exposure;
  plan.toneMap = toneMapNamed(options.toneMap);
  if (plan.spectral) settings.spectralBins = bins;
  std::tie(settings.spectralMin, settings.spectralMax) = parseSpectralRange(options.scene.spectralRange);
  if (!options.part.empty()) plan.part = parsePieceIndex("--part", options.part, 65536);
  if (!options.pass.empty()) plan.pass = parsePieceIndex("--pass", options.pass, kMaxSamplesPerPixel);
  plan.frames = planFrames(options.scene, options.output);
  plan.selected = selectedFrames(options.frame, int(plan.frames.frames.size()));
  settings.targetError = options.targetError;
  settings.adaptive = options.adaptive || options.targetError > 0.0;
  settings.validate({"--spp", "--threads", "--target-error", "--bins"});
  if (settings.adaptive && plan.piece())
    throw std::runtime_error(
        "--adaptive and --target-error render whole images: they cannot be combined with --part "
        "or --pass");
  for (const std::string& file : plan.frames.files) {
    plan.outputs.push_back(OutputPair::fromPath(file));
    if (plan.piece()) checkOutputImagePath(pieceFileName(file, plan.part, plan.pass), true);
  }
  plan.sweeping = !plan.frames.axes.empty();
  plan.keepManifest = (plan.sweeping || !options.manifest.empty()) && options.frame.empty() && !plan.piece();
  plan.manifestPath = options.manifest.empty() ? defaultManifestPath(options) : options.manifest;
  if (plan.keepManifest) checkOutputDirectory(plan.manifestPath, directoryOf(plan.manifestPath));
  return plan;
}

// The manifest of a sweep rendered here, written with every frame pending.
Manifest startManifest(const RenderOptions& options, const RenderPlan& plan) {
  refuseReplacingManifest(plan.manifestPath);
  Manifest manifest;
  manifest.columbaVersion = kColumbaVersion;
  manifest.scene = options.scene.scenePath.empty() ? "<default scene>" : options.scene.scenePath;
  manifest.sceneHash = plan.frames.sceneHash;
  manifest.defines = plan.frames.defines;
  manifest.sweeps = plan.frames.axes;
  manifest.spp = plan.settings.samplesPerPixel;
  manifest.seed = plan.settings.seed;
  for (int f = 0; f < int(plan.frames.frames.size()); ++f) {
    ManifestFrame frame;
    frame.frame = f;
    frame.defines = plan.frames.frameDefines(f);
    frame.seed = plan.settings.seed;
    frame.spp = plan.settings.samplesPerPixel;
    frame.output = plan.outputs[size_t(f)].exr.string();
    manifest.frames.push_back(frame);
  }
  writeManifest(plan.manifestPath, manifest);
  return manifest;
}

// Frame f's scene, with a warning (once per name) for each -D it does not use.
Scene loadFrame(const RenderOptions& options, const RenderPlan& plan, int f, std::set<std::string>& warned) {
  const Defines defines = plan.frames.frameDefines(f);
  ParsedScene parsed = loadFrameScene(options.scene, defines);
  for (const std::string& name : parsed.unusedDefines)
    if (warned.insert(name).second)
      fmt::print(stderr, "warning: -D {}={}: the scene uses no variable ${}, so it has no effect\n", name,
                 defines.at(name), name);
  return Scene(parsed, frameSceneSource(options.scene));
}

// A frame's settings and the record its image keeps of them; `pieceText` says which piece it is.
PieceInfo framePiece(const RenderPlan& plan, int f, const Scene& scene, const std::string& sceneName,
                     RenderSettings& settings, std::string& pieceText) {
  const int spp = settings.samplesPerPixel > 0 ? settings.samplesPerPixel : scene.sensor().sampler().sampleCount();
  settings.samplesPerPixel = spp;
  PieceInfo info;
  info.scene = sceneName;
  info.sceneHash = plan.frames.sceneHash;
  info.defines = describeDefines(plan.frames.frameDefines(f));
  info.seed = settings.seed;
  info.spp = spp;
  // A split render's frame is the film's crop window (the whole film unless cropped): the pieces'
  // windows are relative to it, and merged they make the image a render in one piece makes.
  const PixelRect& crop = scene.sensor().film().crop();
  info.frameWidth = crop.width();
  info.frameHeight = crop.height();
  if (plan.spectral) {
    const auto [lo, hi] = spectralRange(settings, scene.sensor().film(), "--spectral-range");
    info.spectral = fmt::format(
        "{} bins of {:g} nm over {:g}-{:g} nm: mean radiance per nm over each bin "
        "(S0.<centre>nm)",
        settings.spectralBins, (hi - lo) / float(settings.spectralBins), lo, hi);
  }
  if (const ObserverResponse* observer = scene.sensor().film().observer()) info.observer = describeObserver(*observer);
  if (plan.part) {
    // Bands of rows of about equal cost, from a pilot every part computes alike.
    const PieceIndex& part = *plan.part;
    info.part = part;
    if (part.count == 1) {
      info.partBounds = {0, crop.height()};
    } else {
      const std::vector<uint64_t> rowCosts = estimateRowCosts(scene, settings);
      info.partBounds = balancedRowBands({rowCosts.begin() + crop.y0, rowCosts.begin() + crop.y1}, part.count);
    }
    const PixelRect window = partWindow(info.partBounds, part.index, crop.width());
    settings.window = {crop.x0 + window.x0, crop.y0 + window.y0, crop.x0 + window.x1, crop.y0 + window.y1};
    pieceText = fmt::format(", part {} (rows {}-{})", part.str(), window.y0, window.y1 - 1);
  }
  if (plan.pass) {
    info.pass = plan.pass;
    std::tie(info.sampleBegin, info.sampleEnd) = passSamples(*plan.pass, spp);
    settings.sampleBegin = info.sampleBegin;
    settings.sampleEnd = info.sampleEnd;
    pieceText += fmt::format(", pass {} (samples {}:{})", plan.pass->str(), info.sampleBegin, info.sampleEnd);
  }
  return info;
}

// Writes frame f's image (the piece's, or the partial image of an interrupted render); returns
// the files written.
std::string writeFrame(const RenderPlan& plan, int f, const Scene& scene, const RenderSettings& settings,
                       const Image& image, const RenderStats& stats, const ImageMetadata& metadata) {
  const OutputPair& output = plan.outputs[size_t(f)];
  if (plan.piece()) {
    const PixelRect& crop = scene.sensor().film().crop();
    const std::string file = pieceFileName(output.exr.string(), plan.part, plan.pass);
    const std::string written = stats.complete ? file : partialFileName(file);
    const PixelRect window = settings.window.empty() ? crop : settings.window;
    writeEXRWindow(written, image, {window.x0 - crop.x0, window.y0 - crop.y0, window.x1 - crop.x0, window.y1 - crop.y0},
                   crop.width(), crop.height(), metadata);
    return written;
  }
  const OutputPair pair = stats.complete ? output : output.partial();
  writeEXRAndPNG(pair.exr.string(), pair.png.string(), image, metadata, plan.exposure, plan.toneMap);
  return pair.exr.string() + ", " + pair.png.string();
}

struct FrameResult {
  RenderStats stats;
  int spp = 0;
};

// Renders frame f (the i-th of those selected) and writes its image.
FrameResult renderFrame(const RenderOptions& options, const RenderPlan& plan, size_t i, OverallProgress& overall,
                        InterruptionGuard& interruption, std::set<std::string>& warned) {
  const int f = plan.selected[i];
  const std::string label = frameLabel(plan.frames.frames[size_t(f)]);
  // Frames are named by their index in the sweep (0-based, as in the manifest and --frame), and
  // counted among those rendered here from 1: "frame 1 (2 of 3)".
  const std::string which = fmt::format("frame {} ({} of {})", f, i + 1, plan.selected.size());
  if (plan.sweeping) fmt::print(stderr, "Frame {} ({} of {}): {}\n", f, i + 1, plan.selected.size(), label);
  Scene scene = loadFrame(options, plan, f, warned);
  const Film& film = scene.sensor().film();
  RenderSettings settings = plan.settings;
  std::string pieceText;
  PieceInfo info = framePiece(plan, f, scene, frameSceneSource(options.scene).file, settings, pieceText);
  const PixelRect& crop = film.crop();
  const std::string cropText =
      crop.width() == film.width() && crop.height() == film.height()
          ? ""
          : fmt::format(", cropped to {}x{} at ({}, {})", crop.width(), crop.height(), crop.x0, crop.y0);
  fmt::print(stderr, "Rendering {} ({}x{}{}, {} spp{}, {} shapes, {} primitives)\n", info.scene, film.width(),
             film.height(), cropText, settings.samplesPerPixel, pieceText, scene.shapeCount(), scene.primitiveCount());

  overall.done = int(i);
  ProgressReporter progress(plan.sweeping ? which : "render", plan.sweeping ? &overall : nullptr);
  settings.onTileDone = [&](int done, int total) { progress.update(done, total); };
  settings.cancel = &interruption.requested();
  interruption.deferStops();
  RenderStats stats;
  Image image = renderImage(scene, settings, stats);
  progress.finish();

  info.complete = stats.complete;
  info.seconds = stats.seconds;
  const std::string written = writeFrame(plan, f, scene, settings, image, stats, pieceMetadata(info));
  std::string dropped =
      stats.nonFiniteSamples == 0 ? "" : fmt::format(", {} non-finite samples dropped", stats.nonFiniteSamples);
  fmt::print("{} {}{}: {:.2f} s, {:.3f} M samples/s, {:.3f} M rays/s{} -> {}\n",
             stats.complete ? "Rendered" : "Interrupted; wrote the partial image of", info.scene,
             plan.sweeping ? " (" + label + ")" : "", stats.seconds, stats.samples / stats.seconds * 1e-6,
             stats.rays / stats.seconds * 1e-6, dropped, written);
  if (settings.adaptive && stats.complete)
    fmt::print(
        "Adaptive sampling: {} pilot samples per pixel, then {} to {} ({:.1f} on average); predicted relative "
        "RMSE {:.4f}\n",
        stats.pilotSamples, stats.fewestSamples, stats.mostSamples,
        double(stats.samples) / (double(film.width()) * film.height()), stats.predictedRelativeError);
  std::fflush(stdout);
  return {stats, settings.samplesPerPixel};
}

void recordFrame(Manifest& manifest, const RenderPlan& plan, int f, const FrameResult& result) {
  const RenderStats& stats = result.stats;
  ManifestFrame& frame = manifest.frames[size_t(f)];
  frame.status = stats.complete ? "done" : "interrupted";
  frame.spp = result.spp;
  frame.seconds = stats.seconds;
  if (!stats.complete) frame.output = plan.outputs[size_t(f)].partial().exr.string();
  writeManifest(plan.manifestPath, manifest);
}

int runRender(const RenderOptions& options) {
  const RenderPlan plan = planRender(options);
  setImageWriterThreads(plan.settings.threads);
  // Every option checked: the missing directories of the manifest and of the frames rendered
  // here are made (the manifest's first: a manifest it refuses to replace is in one that exists).
  if (plan.keepManifest) makeOutputDirectory(plan.manifestPath, directoryOf(plan.manifestPath));
  Manifest manifest = plan.keepManifest ? startManifest(options, plan) : Manifest{};
  for (int f : plan.selected) plan.outputs[size_t(f)].makeDirectory();
  // Kept until the last image is written. Stops are deferred from the start of each frame's render
  // to its image on disk: a signal while a scene loads ends the process at once, and a second
  // Ctrl-C while writing exits at once.
  InterruptionGuard interruption(
      "\nStopping: finishing the current samples and saving the partial image "
      "(interrupt again to quit at once)\n");
  OverallProgress overall;
  overall.total = int(plan.selected.size());
  overall.start = std::chrono::steady_clock::now();
  std::set<std::string> warned;
  double renderSeconds = 0.0;
  const bool several = plan.sweeping && plan.selected.size() > 1;
  for (size_t i = 0; i < plan.selected.size(); ++i) {
    const int f = plan.selected[i];
    const FrameResult result = renderFrame(options, plan, i, overall, interruption, warned);
    const RenderStats& stats = result.stats;
    renderSeconds += stats.seconds;
    if (plan.keepManifest) recordFrame(manifest, plan, f, result);
    if (!stats.complete) return 128 + interruption.signalNumber();
    interruption.stopAtOnce();
    // A signal while the finished frame was written: the next frame is not begun.
    if (interruption.requested()) return 128 + interruption.signalNumber();
    if (several) {
      overall.done = int(i) + 1;
      fmt::print(stderr, "Frame {} ({} of {}) done in {}; {}\n", f, i + 1, plan.selected.size(),
                 formatDuration(stats.seconds), overall.eta(0.0));
    }
  }
  if (several)
    fmt::print("Rendered {} frames: {:.2f} s rendering, {:.2f} s in all{}\n", plan.selected.size(), renderSeconds,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - overall.start).count(),
               plan.keepManifest ? " (manifest: " + plan.manifestPath + ")" : "");
  return 0;
}
}  // namespace

void addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd =
      app.add_subcommand("render", "Render a Mitsuba-style scene file (or the built-in scene) to EXR + PNG");
  addSceneOptions(cmd, options->scene);
  cmd->add_option(
      "-o,--output", options->output,
      "Output image, .exr or .png: the other of the two is written beside it, its directory made if missing "
      "(default: SCENE.exr)");
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
  cmd->add_option("--exposure", options->exposure,
                  "Brighten (or, negative, darken) the PNG by this many stops; the EXR keeps the linear values "
                  "(default 0)")
      ->check(CLI::Range(-20.0, 20.0));
  cmd->add_option("--tonemap", options->toneMap,
                  "How the PNG maps values above 1: clamp (default) or reinhard (L / (1 + L) on the luminance, "
                  "highlights roll off); the EXR keeps the linear values")
      ->check(CLI::IsMember({"clamp", "reinhard"}));
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
