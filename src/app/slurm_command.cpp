#include "app/slurm_command.h"

#include <fmt/format.h>
#include <sys/stat.h>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <optional>

#include "app/cli_checks.h"
#include "app/scene_options.h"
#include "core/quiet_warnings.h"
#include "core/version.h"
#include "distribute/manifest.h"
#include "distribute/slurm.h"
#include "io/output_directory.h"
#include "render/renderer.h"
#include "samplers/sampler_parameters.h"
#include "scene/scene.h"

namespace columba {

namespace {

namespace fs = std::filesystem;

struct SlurmOptions {
  SceneOptions scene;
  std::string parts = "1", passes = "1";
  std::string partition, time;
  std::string cpusPerTask = "1";
  std::string outDir;
  std::string jobName;
  bool submit = false;
};

std::string nowISO() {
  std::time_t t = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S%z", std::localtime(&t));
  return text;
}

// A finished image (whole or piece) of this render at `path`: complete, of the same scene text,
// defines and seed, and whole: its pixels are read, so that a file cut short (a full disk, a
// copy broken off) is rendered again instead of failing every merge.
bool finishedImage(const std::string& path, const Manifest& manifest, const ManifestFrame& frame) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return false;
  try {
    PieceInfo info = pieceInfoFromFile(path, readEXRFile(path));
    return info.complete && info.sceneHash == manifest.sceneHash && info.defines == describeDefines(frame.defines) &&
           info.seed == frame.seed && (manifest.spp == 0 || info.spp == manifest.spp);
  } catch (const std::exception&) {
    return false;
  }
}

// The first way in which an earlier manifest in the output directory is of another render.
std::string difference(const Manifest& old, const Manifest& now) {
  if (old.sceneHash != now.sceneHash)
    return "its scene file's text differs (hash " + old.sceneHash + ", now " + now.sceneHash + ")";
  if (old.defines != now.defines) return "its -D values differ";
  if (old.sweeps.size() != now.sweeps.size()) return "its sweeps differ";
  for (size_t i = 0; i < old.sweeps.size(); ++i)
    if (old.sweeps[i].name != now.sweeps[i].name || old.sweeps[i].values != now.sweeps[i].values)
      return "its sweep " + old.sweeps[i].spec + " differs from " + now.sweeps[i].spec;
  if (old.spp != now.spp) return fmt::format("its --spp is {}, now {}", old.spp, now.spp);
  if (old.seed != now.seed) return fmt::format("its seed is {}, now {}", old.seed, now.seed);
  if (old.parts != now.parts || old.passes != now.passes)
    return fmt::format("it is split into {} parts x {} passes, now {} x {}", old.parts, old.passes, now.parts,
                       now.passes);
  for (size_t f = 0; f < old.frames.size() && f < now.frames.size(); ++f)
    if (old.frames[f].output != now.frames[f].output)
      return "its frame " + std::to_string(f) + " goes to " + old.frames[f].output + ", now " + now.frames[f].output;
  return "";
}

// Jobs of earlier submissions that are still queued or running ("" if none, or if squeue cannot say).
std::string activeJobs(const Manifest& manifest) {
  std::string ids;
  for (const SlurmSubmission& s : manifest.submissions)
    for (const std::string& id : {s.renderJob, s.mergeJob})
      if (!id.empty()) ids += (ids.empty() ? "" : ",") + id;
  if (ids.empty()) return "";
  ProgramResult r = runProgram({"squeue", "-h", "-o", "%i %T", "-j", ids});
  if (r.status != 0) return "";  // finished jobs are forgotten: "Invalid job id specified"
  std::string active;
  size_t start = 0;
  while (start < r.output.size()) {
    size_t end = r.output.find('\n', start);
    std::string line = r.output.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!line.empty()) active += (active.empty() ? "" : ", ") + line;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return active;
}

// Refuses, before any job is written, a split that every task of a frame would fail at: a
// light-tracing scene (whose image is rendered whole), more parts than the image has rows, more
// passes than samples per pixel. Every frame's scene is loaded once, as its tasks load it.
void checkSplit(const SceneOptions& options, const FramePlan& plan, int sppOption, int parts, int passes) {
  const SourceLocation source = frameSceneSource(options);
  for (size_t f = 0; f < plan.frames.size(); ++f) {
    std::optional<QuietWarnings> quiet;
    if (f > 0) quiet.emplace();  // shown once, for the first frame
    const Scene scene(loadFrameScene(options, plan.frameDefines(int(f))), source);
    std::string frame;
    for (const auto& [name, value] : plan.frames[f].values) frame += fmt::format(", {}={}", name, value);
    if (!frame.empty()) frame = fmt::format(" (frame {}{})", f, frame);
    if (scene.particleTracer())
      throw std::runtime_error(fmt::format(
          "{}{}: its integrator is ptracer, which renders whole images; a Slurm job renders every frame in parts",
          source.file, frame));
    const int rows = scene.sensor().film().crop().height();
    if (parts > rows)
      throw std::runtime_error(fmt::format("--parts {}: the image of {}{} has {} rows, and a part is at least one row",
                                           parts, source.file, frame, rows));
    const int spp = sppOption > 0 ? sppOption : scene.sensor().sampler().sampleCount();
    if (passes > spp)
      throw std::runtime_error(
          fmt::format("--passes {}: {}{} renders {} samples per pixel ({}), and a pass is at least one sample", passes,
                      source.file, frame, spp, sppOption > 0 ? "--spp" : "its sampler's sample_count"));
  }
}

// Every frame and piece of the job in `outDir`, as --out-dir promises (--frames may not leave it).
void checkInside(const fs::path& outDir, const std::string& framesPattern, const std::vector<std::string>& files) {
  for (const std::string& file : files) {
    const fs::path relative = fs::path(file).lexically_normal().lexically_relative(outDir);
    if (relative.empty() || relative == "." || *relative.begin() == "..")
      throw std::runtime_error(
          fmt::format("--frames '{}': '{}' is not in --out-dir '{}'; --frames names the frames "
                      "inside it (give a relative name without '..')",
                      framesPattern, file, outDir.string()));
  }
}

void writeScript(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write '" + path + "'");
  }
  ::chmod(temporary.c_str(), 0755);
  fs::rename(temporary, path);
}

// What a Slurm run does, decided before anything is written: every count checked, every frame's
// image and pieces named.
struct SlurmPlan {
  int parts = 1, passes = 1, cpus = 1, spp = 0;
  std::string stem;
  fs::path outDir, partsDir, logDir, manifestPath;
  // The frames go to the output directory; their pieces to parts/ in it, under the same names.
  SceneOptions frameOptions, pieceOptions;
  FramePlan frames, pieces;
  int64_t taskCount = 0;
};

SlurmPlan planSlurm(const SlurmOptions& options) {
  SlurmPlan sp;
  sp.parts = parseCount("--parts", options.parts, 1, 65536);
  sp.passes = parseCount("--passes", options.passes, 1, kMaxSamplesPerPixel);
  sp.cpus = parseCount("--cpus-per-task", options.cpusPerTask, 1, 4096);
  sp.spp = parseCount("--spp", options.scene.spp, 1, kMaxSamplesPerPixel);
  parseCount("--bins", options.scene.bins, 1, kMaxSpectralBins);
  parseSpectralRange(options.scene.spectralRange);
  sp.stem =
      options.scene.scenePath.empty() ? std::string("default") : fs::path(options.scene.scenePath).stem().string();
  sp.outDir = fs::absolute(options.outDir.empty() ? "slurm-" + sp.stem : options.outDir).lexically_normal();
  sp.partsDir = sp.outDir / "parts";
  sp.logDir = sp.outDir / "logs";
  sp.manifestPath = sp.outDir / "manifest.json";
  sp.frameOptions = sp.pieceOptions = options.scene;
  if (!options.scene.scenePath.empty())
    sp.frameOptions.scenePath = sp.pieceOptions.scenePath =
        fs::absolute(options.scene.scenePath).lexically_normal().string();
  if (!options.scene.framesPattern.empty()) {
    sp.frameOptions.framesPattern = (sp.outDir / options.scene.framesPattern).string();
    sp.pieceOptions.framesPattern = (sp.partsDir / options.scene.framesPattern).string();
  }
  sp.frames = planFrames(sp.frameOptions, (sp.outDir / (sp.stem + ".exr")).string());
  sp.pieces = planFrames(sp.pieceOptions, (sp.partsDir / (sp.stem + ".exr")).string());
  checkInside(sp.outDir, options.scene.framesPattern, sp.frames.files);
  checkInside(sp.outDir, options.scene.framesPattern, sp.pieces.files);
  sp.taskCount = int64_t(sp.frames.frames.size()) * sp.parts * sp.passes;
  if (sp.taskCount > kMostArrayTasks)
    throw std::runtime_error(fmt::format(
        "{} frame{} x --parts {} x --passes {} make {} array tasks, more than {} (Slurm's MaxArraySize allows 1,000 "
        "by default)",
        sp.frames.frames.size(), sp.frames.frames.size() == 1 ? "" : "s", sp.parts, sp.passes, sp.taskCount,
        kMostArrayTasks));
  checkSplit(options.scene, sp.frames, sp.spp, sp.parts, sp.passes);
  checkOutputDirectory(sp.outDir.string(), sp.outDir.string());
  return sp;
}

// The job's batch scripts' settings: every task runs `columba render` on its frame and piece.
SlurmJob slurmJob(const SlurmOptions& options, const SlurmPlan& sp) {
  SlurmJob job;
  job.columba = fs::read_symlink("/proc/self/exe").string();
  job.workDir = fs::current_path().string();
  job.manifestPath = sp.manifestPath.string();
  job.logDir = sp.logDir.string();
  job.jobName = options.jobName.empty() ? "columba-" + sp.stem : options.jobName;
  job.partition = options.partition;
  job.time = options.time;
  job.cpusPerTask = sp.cpus;
  job.frames = int(sp.frames.frames.size());
  job.parts = sp.parts;
  job.passes = sp.passes;
  std::vector<std::string>& args = job.renderArguments;
  if (!sp.frameOptions.scenePath.empty()) args.push_back(sp.frameOptions.scenePath);
  for (const std::string& d : options.scene.defines) args.insert(args.end(), {"-D", d});
  if (sp.spp) args.insert(args.end(), {"--spp", std::to_string(sp.spp)});
  args.insert(args.end(), {"--seed", std::to_string(options.scene.seed)});
  if (options.scene.spectral) args.insert(args.end(), {"--spectral", "--bins", options.scene.bins});
  if (!options.scene.spectralRange.empty()) args.insert(args.end(), {"--spectral-range", options.scene.spectralRange});
  for (const SweepAxis& axis : sp.frames.axes) args.insert(args.end(), {"--sweep", axis.spec});
  if (sp.pieceOptions.framesPattern.empty())
    args.insert(args.end(), {"-o", (sp.partsDir / (sp.stem + ".exr")).string()});
  else
    args.insert(args.end(), {"--frames", sp.pieceOptions.framesPattern});
  return job;
}

// The run's manifest: every frame and piece, with what an earlier run of the same render in the
// output directory recorded (its submissions and times), and the status of each from what is on
// disk.
Manifest slurmManifest(const SlurmOptions& options, const SlurmPlan& sp) {
  Manifest manifest;
  manifest.columbaVersion = kColumbaVersion;
  manifest.scene = sp.frameOptions.scenePath.empty() ? "<default scene>" : sp.frameOptions.scenePath;
  manifest.sceneHash = sp.frames.sceneHash;
  manifest.defines = sp.frames.defines;
  manifest.sweeps = sp.frames.axes;
  manifest.spp = sp.spp;
  manifest.seed = options.scene.seed;
  manifest.parts = sp.parts;
  manifest.passes = sp.passes;
  for (size_t f = 0; f < sp.frames.frames.size(); ++f) {
    ManifestFrame frame;
    frame.frame = int(f);
    frame.defines = sp.frames.frameDefines(int(f));
    frame.seed = options.scene.seed;
    frame.spp = sp.spp;
    frame.output = sp.frames.files[f];
    for (int k = 1; k <= sp.parts; ++k)
      for (int p = 1; p <= sp.passes; ++p) {
        ManifestPiece piece;
        piece.part = PieceIndex{k, sp.parts};
        if (sp.passes > 1) piece.pass = PieceIndex{p, sp.passes};
        piece.file = pieceFileName(sp.pieces.files[f], piece.part, piece.pass);
        frame.pieces.push_back(piece);
      }
    manifest.frames.push_back(frame);
  }
  // A rerun: the same render, whose earlier submissions are kept.
  if (fs::exists(sp.manifestPath)) {
    Manifest old = readManifest(sp.manifestPath.string());
    std::string different = difference(old, manifest);
    if (!different.empty())
      throw std::runtime_error(fmt::format("'{}' is of another render: {}. Use another --out-dir, or remove it",
                                           sp.manifestPath.string(), different));
    manifest.submissions = old.submissions;
    for (size_t f = 0; f < old.frames.size() && f < manifest.frames.size(); ++f) {
      manifest.frames[f].spp = old.frames[f].spp;
      manifest.frames[f].seconds = old.frames[f].seconds;
      for (size_t p = 0; p < old.frames[f].pieces.size() && p < manifest.frames[f].pieces.size(); ++p)
        manifest.frames[f].pieces[p].seconds = old.frames[f].pieces[p].seconds;
    }
  }

  // What is on disk decides what is still to do.
  for (ManifestFrame& frame : manifest.frames) {
    frame.status = finishedImage(frame.output, manifest, frame) ? "done" : "pending";
    for (ManifestPiece& piece : frame.pieces)
      piece.status = finishedImage(piece.file, manifest, frame) ? "done"
                     : fs::exists(partialFileName(piece.file))  ? "interrupted"
                                                                : "pending";
  }
  return manifest;
}

// Prints how to submit the job, or submits it (--submit) and records the submission.
int submitJob(const SlurmOptions& options, const SlurmPlan& sp, const SlurmJob& job, Manifest& manifest,
              const std::string& renderScript, const std::string& mergeScript) {
  MissingWork work = missingWork(
      manifest, [](const ManifestFrame& f) { return f.status == "done"; },
      [](const ManifestPiece& p) { return p.status == "done"; });

  fmt::print("{} frame{} x {} part{} x {} pass{} = {} array tasks; {} to render, {} frame{} to merge\n", job.frames,
             job.frames == 1 ? "" : "s", sp.parts, sp.parts == 1 ? "" : "s", sp.passes, sp.passes == 1 ? "" : "es",
             sp.taskCount, work.tasks.size(), work.framesToMerge.size(), work.framesToMerge.size() == 1 ? "" : "s");
  fmt::print("Scripts: {}, {}\nManifest: {}\nLogs: {}/ (render_JOB_TASK.log, merge_JOB.log)\n", renderScript,
             mergeScript, sp.manifestPath.string(), sp.logDir.string());
  if (work.framesToMerge.empty()) {
    fmt::print("Nothing to do: every frame is merged.\n");
    return 0;
  }
  if (sp.taskCount > 1001)
    fmt::print(stderr, "warning: task indices reach {}; Slurm's default MaxArraySize (1001) allows at most 1000\n",
               sp.taskCount - 1);
  const std::string tasks = arraySpec(work.tasks);
  if (!options.submit) {
    fmt::print("Submit with:\n");
    if (work.tasks.empty()) {
      fmt::print("  {}\n", shellCommand(mergeSubmitCommand(mergeScript, "")));
    } else {
      fmt::print("  render=$({})\n", shellCommand(renderSubmitCommand(job, renderScript, tasks)));
      std::vector<std::string> merge = mergeSubmitCommand(mergeScript, "RENDER");
      std::string line = shellCommand(merge);
      line.replace(line.find("afterok:RENDER"), 14, "afterok:${render%;*}");
      fmt::print("  {}\n(or run this command again with --submit)\n", line);
    }
    return 0;
  }

  if (std::string active = activeJobs(manifest); !active.empty())
    throw std::runtime_error("jobs of an earlier submission are still queued or running (" + active +
                             "); wait for them (squeue) or cancel them (scancel JOBID) first");
  SlurmSubmission submission;
  submission.submitted = nowISO();
  submission.tasks = tasks;
  auto submitOne = [](const std::vector<std::string>& command) {
    fmt::print("{}\n", shellCommand(command));
    ProgramResult r = runProgram(command);
    if (r.status != 0)
      throw std::runtime_error(fmt::format("{} failed (status {}): {}", command.front(), r.status, r.output));
    return parseJobId(r.output);
  };
  if (!work.tasks.empty()) submission.renderJob = submitOne(renderSubmitCommand(job, renderScript, tasks));
  try {
    submission.mergeJob = submitOne(mergeSubmitCommand(mergeScript, submission.renderJob));
  } catch (...) {
    manifest.submissions.push_back(submission);  // the render job is queued: recorded all the same
    writeManifest(sp.manifestPath.string(), manifest);
    throw;
  }
  manifest.submissions.push_back(submission);
  writeManifest(sp.manifestPath.string(), manifest);
  if (!submission.renderJob.empty())
    fmt::print("Submitted render job {} (array tasks {}) and merge job {} (runs after every task succeeded)\n",
               submission.renderJob, tasks, submission.mergeJob);
  else
    fmt::print("Submitted merge job {} (every piece is rendered)\n", submission.mergeJob);
  fmt::print("render job: {}\nmerge job: {}\n", submission.renderJob.empty() ? "-" : submission.renderJob,
             submission.mergeJob);
  return 0;
}

int runSlurm(const SlurmOptions& options) {
  const SlurmPlan sp = planSlurm(options);
  const SlurmJob job = slurmJob(options, sp);
  // Written before anything is created, so that a value no script can hold is refused first.
  const std::string renderText = renderBatchScript(job), mergeText = mergeBatchScript(job);
  makeOutputDirectory(sp.outDir.string(), sp.outDir.string());
  for (const std::string& file : sp.frames.files) makeOutputDirectory(file, directoryOf(file));
  for (const std::string& file : sp.pieces.files) makeOutputDirectory(file, directoryOf(file));
  makeOutputDirectory(sp.logDir.string(), sp.logDir.string());
  Manifest manifest = slurmManifest(options, sp);
  const std::string renderScript = (sp.outDir / "render.sbatch").string(),
                    mergeScript = (sp.outDir / "merge.sbatch").string();
  manifest.renderScript = renderScript;
  manifest.mergeScript = mergeScript;
  manifest.logDir = sp.logDir.string();
  writeScript(renderScript, renderText);
  writeScript(mergeScript, mergeText);
  writeManifest(sp.manifestPath.string(), manifest);
  return submitJob(options, sp, job, manifest, renderScript, mergeScript);
}

}  // namespace

void addSlurmCommand(CLI::App& app) {
  auto options = std::make_shared<SlurmOptions>();
  CLI::App* cmd = app.add_subcommand(
      "slurm",
      "Write (and with --submit, submit) a Slurm job array rendering a sweep or a frame in pieces, and a "
      "merge job after it; run again, it submits only what is missing");
  addSceneOptions(cmd, options->scene);
  cmd->add_option("--parts", options->parts, "Bands of rows each frame is split into (one array task each)");
  cmd->add_option("--passes", options->passes, "Ranges of sample indices each part is split into (default 1)");
  cmd->add_option("--partition", options->partition, "Slurm partition (default: the cluster's)");
  cmd->add_option("--time", options->time, "Time limit of each task, as sbatch --time takes it (e.g. 30:00)");
  cmd->add_option("--cpus-per-task", options->cpusPerTask, "CPUs of each task, its render threads (default 1)");
  cmd->add_option("--out-dir", options->outDir,
                  "Where the frames, parts/, logs/, the batch scripts and manifest.json go (default: slurm-SCENE); "
                  "--frames names the frames inside it");
  cmd->add_option("--job-name", options->jobName, "Slurm job name prefix (default: columba-SCENE)");
  cmd->add_flag("--submit", options->submit, "Submit the jobs (sbatch) and print their ids");
  cmd->callback([options] {
    int code = runSlurm(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace columba
