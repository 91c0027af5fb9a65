#include "app/fit_command.h"

#include <fmt/format.h>

#include <filesystem>

#include "fit/fit_report.h"
#include "fit/scene_fit.h"
#include "fit/spectra_fit.h"
#include "io/data_files.h"
#include "io/output_directory.h"

namespace columba {

namespace {

namespace fs = std::filesystem;

struct FitOptions {
  std::string scenePath, targetPath, maskPath, spectraPath, outputDir = "fit";
  std::vector<std::string> vary, defines;
  int spp = 0;
  uint64_t seed = 0;
  int threads = 0;
  std::string scale = "free", loss = "mse";
  int maxEvaluations = 300;
  double maxSeconds = 120.0;
  double rise = 0.1;
  std::string global = "GN_CRS2_LM";
  SpectraGeometry geometry;  // of spectra without directions
  float aperture = 0.0f;     // the instrument's half-angle, degrees
  std::string view = "mirror";
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

std::string describeValues(const std::vector<FitParameter>& parameters, const std::vector<double>& values) {
  std::string text;
  for (size_t i = 0; i < values.size(); ++i)
    text += fmt::format("{}{}={:.5g}", text.empty() ? "" : " ", parameters[i].name, values[i]);
  return text;
}

// A line when the best loss improves, and every 25 evaluations so a slow fit still shows life.
FitProgress terminalProgress(const std::vector<FitParameter>& parameters) {
  return [parameters, lastBest = HUGE_VAL](const Evaluation& latest, const Evaluation& best) mutable {
    if (best.loss.loss >= lastBest && latest.index % 25 != 0) return;
    lastBest = best.loss.loss;
    fmt::print(stderr, "eval {:4d} {:7} {:7.1f} s  best loss {:.6g} (scale {:.4g})  {}\n", latest.index, latest.stage,
               latest.seconds, best.loss.loss, best.loss.scale, describeValues(parameters, best.values));
  };
}

void printSummary(const FitResult& r, const fs::path& dir) {
  fmt::print("Fitted in {} evaluations, {:.1f} s ({:.3f} s per evaluation); profiles: {} more, {:.1f} s in all\n",
             r.evaluations, r.seconds, r.seconds / std::max(r.evaluations, 1), r.profileEvaluations, r.totalSeconds);
  fmt::print("loss {:.6g}, scale {:.6g}; intervals where the loss stays below (1 + {:g}) x minimum\n", r.loss.loss,
             r.loss.scale, r.profileRise);
  for (size_t i = 0; i < r.parameters.size(); ++i) {
    const LossProfile& p = r.profiles[i];
    fmt::print("  {:>8} = {:<10.5g} [{:.5g}{}, {:.5g}{}]\n", r.parameters[i].name, r.values[i], p.lower,
               p.lowerAtBound ? " (bound)" : "", p.upper, p.upperAtBound ? " (bound)" : "");
    if (p.solutions.size() > 1) {
      std::string list;
      for (const ProfileSolution& s : p.solutions)
        list += fmt::format("{}{:.5g} [{:.5g}, {:.5g}] (loss {:.4g})", list.empty() ? "" : "; ", s.value, s.lower,
                            s.upper, s.loss);
      fmt::print("           the data admit {} solutions for {}: {}\n", p.solutions.size(), r.parameters[i].name, list);
    }
  }
  fmt::print("-> {}\n", dir.string());
}

int runFitCommand(const FitOptions& o) {
  if (o.vary.empty()) throw std::runtime_error("--vary NAME=LO:HI[:START] is needed at least once");
  if (o.spectraPath.empty() == o.scenePath.empty())
    throw std::runtime_error("give either a scene (with --target) or --spectra, not both or neither");
  std::vector<FitParameter> parameters;
  for (const std::string& text : o.vary) parameters.push_back(parseFitParameter(text));
  const Defines defines = parseDefines(o.defines);
  std::vector<std::string> fixed;
  for (const auto& define : defines) fixed.push_back(define.first);

  FitSettings fit;
  fit.optimizer.maxEvaluations = o.maxEvaluations;
  fit.optimizer.maxSeconds = o.maxSeconds;
  fit.optimizer.globalAlgorithm = o.global;
  fit.profileRise = o.rise;
  fit.progress = terminalProgress(parameters);
  // Before the output directory is made: the library checks the fits Python runs alike.
  checkFitSettings(parameters, fit, fixed);
  const fs::path dir = o.outputDir;
  fs::create_directories(dir);
  nlohmann::json settings = {
      {"vary", o.vary},
      {"defines", o.defines},
      {"loss", o.loss},
      {"scale", o.scale},
      {"max_evaluations", o.maxEvaluations},
      {"max_seconds", o.maxSeconds},
      {"optimizer",
       "NLopt " + o.global + ", then LN_BOBYQA (LN_NELDERMEAD for one parameter) from its 3 best distinct points"}};
  FitResult result;
  if (!o.spectraPath.empty()) {
    SpectraFitSettings s;
    SpectraGeometry geometry = o.geometry;
    geometry.view = o.view == "normal" ? SpectraGeometry::View::Normal : SpectraGeometry::View::Mirror;
    s.samples = readSpectraCSV(o.spectraPath, geometry);
    s.fixed = std::map<std::string, std::string>(defines.begin(), defines.end());
    s.aperture.halfAngleDeg = o.aperture;
    s.parameters = parameters;
    s.loss = parseLossKind(o.loss);
    s.scale = parseScaleMode(o.scale);
    s.fit = fit;
    fmt::print(stderr, "Fitting {} parameters to {} spectral samples of {}\n", parameters.size(), s.samples.size(),
               o.spectraPath);
    SpectraFitResult fitted = fitSpectra(s);
    result = fitted.fit;
    if (const std::optional<std::string> warning = implausibleScaleWarning(result.loss.scale))
      fmt::print(stderr, "warning: {}: {}\n", o.spectraPath, *warning);
    settings["spectra"] = o.spectraPath;
    const LinePlot spectra = spectraPlot(s.samples, fitted.model, result.loss.scale);
    for (const char* extension : {".png", ".svg", ".pdf"})
      writeLinePlot((dir / (std::string("spectra") + extension)).string(), spectra, 1000, 640);
  } else {
    if (o.targetPath.empty()) throw std::runtime_error("--target MEASURED.exr is needed to fit a scene");
    if (!fs::is_regular_file(o.scenePath))
      throw std::runtime_error("scene file '" + o.scenePath + "' does not exist or is not a regular file");
    SceneFitSettings s;
    s.scenePath = o.scenePath;
    s.defines = defines;
    s.target = readEXR(o.targetPath);
    if (!o.maskPath.empty()) s.mask = readPNG(o.maskPath);
    s.parameters = parameters;
    s.samplesPerPixel = o.spp;
    s.seed = o.seed;
    s.threads = o.threads;
    s.loss = parseLossKind(o.loss);
    s.scale = parseScaleMode(o.scale);
    s.fit = fit;
    fmt::print(stderr, "Fitting {} parameters of {} to {} ({}x{})\n", parameters.size(), o.scenePath, o.targetPath,
               s.target.width, s.target.height);
    SceneFitResult fitted = fitScene(s);
    result = fitted.fit;
    settings.update({{"scene", o.scenePath},
                     {"target", o.targetPath},
                     {"mask", o.maskPath},
                     {"spp", o.spp},
                     {"seed", o.seed},
                     {"width", s.target.width},
                     {"height", s.target.height}});
    writePNG((dir / "compare.png").string(), compareImage(s.target, fitted.render, result.loss.scale, s.mask));
  }
  writeJSON((dir / "fit.json").string(), fitRecord(result, settings));
  writeCSV((dir / "history.csv").string(), historyTable(result));
  writePNG((dir / "profiles.png").string(), profilesImage(result));
  const std::vector<LinePlot> profiles = profilePlots(result);
  for (size_t i = 0; i < profiles.size(); ++i)  // each as vectors too, for papers
    for (const char* extension : {".svg", ".pdf"})
      writeLinePlot((dir / ("profile_" + safeForFileName(result.parameters[i].name) + extension)).string(), profiles[i],
                    1000, 640);
  printSummary(result, dir);
  return 0;
}

}  // namespace

void addFitCommand(CLI::App& app) {
  auto o = std::make_shared<FitOptions>();
  CLI::App* cmd = app.add_subcommand(
      "fit", "Fit scene variables to a measured image (or barbule parameters to measured spectra), with uncertainties");
  cmd->add_option("scene", o->scenePath, "Scene file (XML) whose $variables are fitted");
  cmd->add_option("--target", o->targetPath, "Measured image (EXR, linear RGB); the film is set to its size");
  cmd->add_option("--vary", o->vary, "A parameter to fit: NAME=LO:HI[:START] (repeatable; START: the middle)")
      ->allow_extra_args(false);
  cmd->add_option("-D,--define", o->defines,
                  "Fix a scene variable (or barbule parameter with --spectra): -D name=value")
      ->allow_extra_args(false);
  cmd->add_option("--mask", o->maskPath, "PNG of the target's size: only pixels brighter than half count");
  cmd->add_option(
      "--spectra", o->spectraPath,
      "Fit barbule parameters to spectra (reflectance factor pi f): CSV with theta_i, phi_i, theta_o, phi_o "
      "(deg), wavelength_nm, reflectance; or a wavelength column (wl, wavelength_nm, ...) and a column per "
      "spectrum, as pavo and columba bsdf --mode specular write them");
  cmd->add_option("--theta-i", o->geometry.thetaI,
                  "With --spectra: the light's polar angle (deg) of spectra without directions, one or one per column")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 89.9));
  cmd->add_option("--aperture", o->aperture,
                  "With --spectra: the instrument's half-angle (deg; numerical aperture = its sine): the model is "
                  "averaged over the illumination and collection cones (default 0, a point measurement)");
  cmd->add_option("--phi-i", o->geometry.phiI,
                  "With --spectra: the light's azimuth (deg; default 0, across the barbules)");
  cmd->add_option(
         "--geometry", o->view,
         "With --spectra: where spectra without directions were seen: mirror (theta_i, phi_i + 180; default) or "
         "normal (along the vane normal)")
      ->check(CLI::IsMember({"mirror", "normal"}));
  cmd->add_option("--spp", o->spp, "Samples per pixel of every render (default: the scene's sampler)")
      ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--seed", o->seed, "Random seed, the same for every render (common random numbers)");
  cmd->add_option("--threads", o->threads, "Render threads (default: all cores)")->check(CLI::Range(1, 65536));
  cmd->add_option("--scale", o->scale, "free: fit the exposure (one global scale, closed form); fixed: scale 1")
      ->capture_default_str();
  cmd->add_option("--loss", o->loss, "mse, log or relative (squared differences, averaged)")->capture_default_str();
  cmd->add_option("--max-evals", o->maxEvaluations, "Evaluation budget of the optimiser")->capture_default_str();
  cmd->add_option("--max-seconds", o->maxSeconds, "Time budget of the optimiser (s)")->capture_default_str();
  cmd->add_option("--global", o->global,
                  "NLopt algorithm of the global stage (GN_CRS2_LM, GN_DIRECT, GN_DIRECT_L, ...)")
      ->capture_default_str();
  cmd->add_option("--rise", o->rise, "Uncertainty intervals: where the loss stays below (1 + rise) x its minimum")
      ->capture_default_str();
  cmd->add_option("-o,--output", o->outputDir, "Output directory (created if missing)")->capture_default_str();
  cmd->callback([o] {
    int code = runFitCommand(*o);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace columba
