// `columba fit`'s library: the loss and its scale, parameter parsing, and recovery of known
// barbule parameters from perturbed renders and spectra.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "fit/fit_parameter.h"
#include "fit/fit_report.h"
#include "fit/scaled_loss.h"
#include "fit/scene_fit.h"
#include "fit/spectra_fit.h"

namespace columba {
namespace {

TEST(FitParameter, ParsesBoundsAndStart) {
  FitParameter p = parseFitParameter("height=0.4:0.7:0.5");
  EXPECT_EQ(p.name, "height");
  EXPECT_DOUBLE_EQ(p.lower, 0.4);
  EXPECT_DOUBLE_EQ(p.upper, 0.7);
  EXPECT_DOUBLE_EQ(p.startValue(), 0.5);
  EXPECT_DOUBLE_EQ(parseFitParameter("b=0.1:0.3").startValue(), 0.2);
  for (const char* bad : {"height", "=1:2", "h=1", "h=2:1", "h=1:2:3", "h=1:x", "h=1:2:3:4"})
    EXPECT_THROW(parseFitParameter(bad), std::runtime_error) << bad;
}

TEST(ScaledLoss, FreeScaleIsTheLeastSquaresExposure) {
  std::vector<float> model = {1.0f, 2.0f, 3.0f, 0.5f};
  std::vector<float> target;
  for (float m : model) target.push_back(1.7f * m);
  LossValue free = ScaledLoss(target, {}, LossKind::MSE, ScaleMode::Free)(model);
  EXPECT_NEAR(free.scale, 1.7, 1e-6);
  EXPECT_NEAR(free.loss, 0.0, 1e-10);
  LossValue fixed = ScaledLoss(target, {}, LossKind::MSE, ScaleMode::Fixed)(model);
  EXPECT_DOUBLE_EQ(fixed.scale, 1.0);
  EXPECT_NEAR(fixed.loss, 0.49 * (1 + 4 + 9 + 0.25) / 4, 1e-5);
  // A zero weight leaves a value out.
  std::vector<float> off = target;
  off[3] = 100.0f;
  EXPECT_NEAR(ScaledLoss(off, {1, 1, 1, 0}, LossKind::Relative, ScaleMode::Free)(model).loss, 0.0, 1e-10);
  EXPECT_GT(ScaledLoss(off, {}, LossKind::Log, ScaleMode::Free)(model).loss, 0.1);
}

// The scatterometer set-up of scenes/bsdf_visualization_oblique.xml with the barbule's film
// thickness, b, mu and H as variables, at 32 x 32 pixels.
const char* kScene = R"(<scene version="3.0.0">
  <default name="height" value="0.58"/> <default name="b" value="0.25"/>
  <default name="mu" value="-0.35"/> <default name="H" value="1.25"/>
  <default name="radiance" value="30"/>
  <integrator type="direct">
    <integer name="emitter_samples" value="1"/> <integer name="bsdf_samples" value="0"/>
  </integrator>
  <sensor type="bsdfvisualizer">
    <film type="hdrfilm"> <integer name="width" value="8"/> <integer name="height" value="8"/> </film>
    <sampler type="ldsampler"> <integer name="sample_count" value="4"/> </sampler>
  </sensor>
  <shape type="rectangle">
    <bsdf type="barbulebsdfev">
      <float name="height" value="$height"/> <float name="b" value="$b"/>
      <float name="mu" value="$mu"/> <float name="H" value="$H"/>
    </bsdf>
    <transform name="to_world"> <rotate z="1" angle="-50"/> </transform>
  </shape>
  <shape type="disk">
    <transform name="to_world">
      <scale x="0.1" y="0.1" z="1"/> <rotate x="1" angle="180"/> <translate z="1"/> <rotate y="1" angle="30"/>
    </transform>
    <emitter type="area"> <spectrum name="radiance" value="$radiance"/> </emitter>
  </shape>
</scene>)";

// The scene file, one per test process: CTest runs the tests of this file in parallel processes.
std::string writeScene() {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("columba_test_fit_scene_" + std::to_string(::getpid()) + ".xml");
  std::ofstream(path) << kScene;
  return path.string();
}

struct Truth {
  double height, b, mu, H;
};
// Names the cases in test output by their parameters.
void PrintTo(const Truth& t, std::ostream* os) {
  *os << "height " << t.height << " b " << t.b << " mu " << t.mu << " H " << t.H;
}

std::vector<FitParameter> barbuleParameters() {
  return {parseFitParameter("height=0.4:0.7:0.55"), parseFitParameter("b=0.15:0.5:0.3"),
          parseFitParameter("mu=-0.7:0.4:-0.1"), parseFitParameter("H=1.2:2.5:1.7")};
}

// Poisson-like noise: standard deviation `level` x sqrt(value x mean), so `level` relative noise at
// the mean brightness; and an exposure the fit does not know.
std::vector<float> perturb(std::vector<float> values, double exposure, double level, uint32_t seed) {
  double mean = 0.0;
  for (float v : values) mean += exposure * v / double(values.size());
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  for (float& v : values) {
    const double scaled = exposure * v;
    v = float(scaled + level * std::sqrt(std::max(scaled, 0.0) * mean) * normal(rng));
  }
  return values;
}

SceneFitSettings sceneSettings(const std::string& scene) {
  SceneFitSettings s;
  s.scenePath = scene;
  s.target = Image(32, 32);
  s.samplesPerPixel = 4;
  s.threads = 2;
  s.parameters = barbuleParameters();
  // 600 evaluations sufficed with pbrt's visible wavelength density; with the RGB-matching one
  // (another noise pattern in the 4 spp renders) two of the five cases ended in a wrong basin, and
  // 1200 find every truth's (810-1058 used).
  s.fit.optimizer.maxEvaluations = 1200;
  s.fit.optimizer.maxSeconds = 30.0;
  return s;
}

class ImageRecovery : public ::testing::TestWithParam<Truth> {};

TEST_P(ImageRecovery, RecoversTheBarbuleFromANoisyRenderOfUnknownExposure) {
  const Truth truth = GetParam();
  SceneFitSettings s = sceneSettings(writeScene());
  Image target = renderSceneWith(s, {truth.height, truth.b, truth.mu, truth.H});
  const double exposure = 0.5 + 1.5 * (truth.height - 0.4) / 0.3;  // in [0.5, 2]
  target.rgb = perturb(target.rgb, exposure, 0.02, 7);
  s.target = target;
  SceneFitResult result = fitScene(s);
  const FitResult& r = result.fit;
  // From one 32 x 32 view at 4 spp the film thickness, b and mu are recovered well within 0.005 um,
  // 0.03 and 0.05 (measured worst: 0.0001 um, 0.026, 0.007). H is not always constrained: where
  // its interval is narrow it is recovered within 0.12 (worst 0.11); elsewhere the fit must say
  // so with an interval at least 0.3 wide (the untilted barbule fits H 1.30 for 1.8 with a loss
  // below the truth's: the image does not tell them apart). The exposure follows within 15 % where H
  // is constrained.
  EXPECT_NEAR(r.values[0], truth.height, 0.005);
  EXPECT_NEAR(r.values[1], truth.b, 0.03);
  EXPECT_NEAR(r.values[2], truth.mu, 0.05);
  const double hWidth = r.profiles[3].upper - r.profiles[3].lower;
  EXPECT_TRUE(std::abs(r.values[3] - truth.H) <= 0.12 || hWidth >= 0.3)
      << "H " << r.values[3] << " for " << truth.H << ", interval width " << hWidth;
  // Where H is not constrained the exposure trades off against it (H 1.84 for 1.5 gives a scale of
  // 0.86-0.87 for 0.75, the value depending on the build's floating-point code): 25 % there.
  const bool hConstrained = hWidth < 0.3;
  EXPECT_NEAR(r.loss.scale, exposure, (hConstrained ? 0.15 : 0.25) * exposure);
  const double truthLoss = ScaledLoss(s.target.rgb, {}, LossKind::MSE, ScaleMode::Free)(
                               renderSceneWith(s, {truth.height, truth.b, truth.mu, truth.H}).rgb)
                               .loss;
  // The intervals hold the fitted values and are narrow for these constrained parameters.
  for (size_t i = 0; i < r.values.size(); ++i) {
    EXPECT_LE(r.profiles[i].lower, r.values[i]);
    EXPECT_GE(r.profiles[i].upper, r.values[i]);
  }
  EXPECT_LT(r.profiles[0].upper - r.profiles[0].lower, 0.05);
  std::printf(
      "truth %.3f %.3f %.3f %.3f -> fitted %.4f %.4f %.4f %.4f scale %.3f/%.3f, loss %.3g (truth %.3g), %d "
      "evaluations\n",
      truth.height, truth.b, truth.mu, truth.H, r.values[0], r.values[1], r.values[2], r.values[3], r.loss.scale,
      exposure, r.loss.loss, truthLoss, r.evaluations);
  for (size_t i = 0; i < r.values.size(); ++i)
    std::printf("  %-6s [%.4f, %.4f]\n", r.parameters[i].name.c_str(), r.profiles[i].lower, r.profiles[i].upper);
}

// The reference scenes' barbule (green and purple film), a round sparse one, a thin dense one and
// an untilted one.
INSTANTIATE_TEST_SUITE_P(ParameterSets, ImageRecovery,
                         ::testing::Values(Truth{0.58, 0.25, -0.35, 1.25}, Truth{0.51, 0.25, -0.35, 1.4},
                                           Truth{0.65, 0.45, 0.25, 2.2}, Truth{0.45, 0.18, -0.6, 1.5},
                                           Truth{0.62, 0.35, 0.0, 1.8}));

TEST(SceneFit, AnUnconstrainedParameterGetsAnIntervalReachingItsBounds) {
  // With the exposure free, the light's radiance only scales the image: no image constrains it.
  SceneFitSettings s = sceneSettings(writeScene());
  s.parameters = {parseFitParameter("height=0.4:0.7:0.5"), parseFitParameter("radiance=5:100:20")};
  s.target = renderSceneWith(s, {0.6, 30.0});
  s.fit.optimizer.maxEvaluations = 60;
  FitResult r = fitScene(s).fit;
  EXPECT_NEAR(r.values[0], 0.6, 0.005);
  EXPECT_TRUE(r.profiles[1].lowerAtBound && r.profiles[1].upperAtBound);
  EXPECT_DOUBLE_EQ(r.profiles[1].lower, 5.0);
  EXPECT_DOUBLE_EQ(r.profiles[1].upper, 100.0);
  EXPECT_FALSE(r.profiles[0].lowerAtBound || r.profiles[0].upperAtBound);
}

TEST(SceneFit, NamesAVariableTheSceneDoesNotUse) {
  SceneFitSettings s = sceneSettings(writeScene());
  s.parameters = {parseFitParameter("thickness=0.4:0.7")};
  try {
    renderSceneWith(s, {0.5});
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("$thickness"), std::string::npos) << e.what();
  }
}

namespace {
// The model's specular spectra at three light angles, 400-700 nm every 5 nm, with 2 % relative noise.
std::vector<SpectraSample> noisySpecularSpectra(const BarbuleParameters& truth, unsigned seed) {
  std::vector<SpectraSample> samples;
  for (float theta : {10.0f, 30.0f, 50.0f})
    for (float lambda = 400.0f; lambda <= 700.0f; lambda += 5.0f)
      samples.push_back({theta, 0.0f, theta, 180.0f, lambda, 0.0f});
  std::vector<float> clean = modelSpectra(truth, samples);
  std::mt19937 rng(seed);
  std::normal_distribution<float> normal;
  for (size_t i = 0; i < samples.size(); ++i) samples[i].reflectance = clean[i] * (1.0f + 0.02f * normal(rng));
  return samples;
}
}  // namespace

TEST(SpectraFit, RecoversTheFilmThicknessFromNoisySpectra) {
  SpectraFitSettings s;
  s.samples = noisySpecularSpectra(barbuleParametersWith({{"height", 0.53}, {"b", 0.3}}), 3);
  s.parameters = {parseFitParameter("height=0.4:0.7:0.62"), parseFitParameter("b=0.15:0.5:0.2")};
  s.fit.optimizer.maxEvaluations = 200;
  SpectraFitResult r = fitSpectra(s);
  EXPECT_NEAR(r.fit.values[0], 0.53, 0.003);
  EXPECT_LT(r.fit.profiles[0].upper - r.fit.profiles[0].lower, 0.02);
  std::printf("spectra: height 0.53 -> %.4f [%.4f, %.4f], b 0.3 -> %.4f, %d evaluations\n", r.fit.values[0],
              r.fit.profiles[0].lower, r.fit.profiles[0].upper, r.fit.values[1], r.fit.evaluations);
}

namespace {
// Fits the one varied parameter of `s` and expects `truth` within `tolerance` and inside its interval.
void expectOneParameterRecovered(const SpectraFitSettings& s, const char* what, double truth, double tolerance) {
  SpectraFitResult r = fitSpectra(s);
  std::printf("spectra: %s %g -> %.4f [%.4f, %.4f], %d evaluations\n", what, truth, r.fit.values[0],
              r.fit.profiles[0].lower, r.fit.profiles[0].upper, r.fit.evaluations);
  EXPECT_NEAR(r.fit.values[0], truth, tolerance) << what;
  EXPECT_LT(r.fit.profiles[0].lower, truth) << what;
  EXPECT_GT(r.fit.profiles[0].upper, truth) << what;
}
}  // namespace

TEST(SpectraFit, RecoversTheCrossSectionsExponentFromNoisySpectra) {
  // The shape of the cross-section, not only its film, leaves its mark on specular spectra: a
  // squarer barbule concentrates its normals.
  SpectraFitSettings s;
  s.samples = noisySpecularSpectra(barbuleParametersWith({{"profile_exponent", 4.0}}), 5);
  s.parameters = {parseFitParameter("profile_exponent=2:10:3")};
  s.fit.optimizer.maxEvaluations = 120;
  expectOneParameterRecovered(s, "profile_exponent", 4.0, 0.1);
}

TEST(SpectraFit, RecoversARodDiameterNamedAsAVariableInTheLayers) {
  // A biologist's question: how large are the melanosomes of the rows that make this spectrum?
  const std::string layers = "[rods(melanin, $d, 0.15), keratin:0.04] x 4";
  SpectraFitSettings s;
  s.samples = noisySpecularSpectra(barbuleParametersWith({{"d", 0.1}}, {{"layers", layers}, {"height", "0.1"}}), 7);
  s.fixed = {{"layers", layers}, {"height", "0.1"}};
  s.parameters = {parseFitParameter("d=0.06:0.14:0.08")};
  s.fit.optimizer.maxEvaluations = 80;
  expectOneParameterRecovered(s, "rod diameter", 0.1, 0.003);
  // A $name no varied parameter gives is an error naming it, before any evaluation.
  s.parameters = {parseFitParameter("height=0.05:0.2")};
  s.fixed = {{"layers", layers}};
  try {
    fitSpectra(s);
    ADD_FAILURE() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("$d"), std::string::npos) << e.what();
  }
}

// Checked by the fit library, so that Python's fit and fit_spectra refuse what `columba fit` does:
// they accepted max_evals 0, negative budgets and rises, a name varied twice or also fixed, and
// negative sample and thread counts.
TEST(FitSettings, WhatNoFitCanRunWithIsRefusedBeforeAnyEvaluation) {
  auto spectraError = [](auto change) {
    SpectraFitSettings s;
    s.samples = {{10.0f, 0.0f, 10.0f, 180.0f, 500.0f, 0.2f}};
    s.parameters = {parseFitParameter("height=0.4:0.7")};
    change(s);
    try {
      fitSpectra(s);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  auto contains = [](const std::string& message, const char* part) {
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: '" << message << "'";
  };
  contains(spectraError([](SpectraFitSettings& s) { s.fit.optimizer.maxEvaluations = 0; }), "at least 3");
  contains(spectraError([](SpectraFitSettings& s) { s.fit.optimizer.maxSeconds = -1.0; }), "not -1");
  contains(spectraError([](SpectraFitSettings& s) { s.fit.profileRise = -0.1; }), "rise must be positive");
  contains(spectraError([](SpectraFitSettings& s) { s.parameters.push_back(parseFitParameter("height=0.5:0.6")); }),
           "'height' is varied twice");
  contains(spectraError([](SpectraFitSettings& s) { s.fixed["height"] = "0.5"; }), "'height' is both held fixed");
  contains(spectraError([](SpectraFitSettings& s) { s.parameters.clear(); }), "at least one parameter");

  auto sceneError = [](auto change) {
    SceneFitSettings s;
    s.scenePath = "never-loaded.xml";
    s.parameters = {parseFitParameter("height=0.4:0.7")};
    change(s);
    try {
      fitScene(s);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  contains(sceneError([](SceneFitSettings& s) { s.samplesPerPixel = -1; }), "not -1");
  contains(sceneError([](SceneFitSettings& s) { s.threads = -2; }), "not -2");
  contains(sceneError([](SceneFitSettings& s) { s.defines["height"] = "0.5"; }), "'height' is both held fixed");
}

TEST(SpectraFit, AThicknessInNanometresIsRefusedNamingTheBounds) {
  SpectraFitSettings s;
  s.samples = {{20.0f, 0.0f, 20.0f, 180.0f, 500.0f, 0.1f}};
  s.parameters = {parseFitParameter("height=400:600")};
  try {
    fitSpectra(s);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("height=400:600: a film"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("did you give nm?"), std::string::npos) << e.what();
  }
  s.parameters = {parseFitParameter("height=0.4:0.6")};
  s.fit.optimizer.maxEvaluations = 20;
  EXPECT_NO_THROW(fitSpectra(s));
}

TEST(SpectraFit, HeldValuesMayBeNamesAsInAScene) {
  // -D preset=dove-purple and -D film_ior=1.56 hold the barbule at a preset and an index.
  const BarbuleParameters purple =
      barbuleParametersWith({{"height", 0.55}}, {{"preset", "dove-purple"}, {"film_ior", "1.56"}});
  const BarbuleParameters preset = *barbulePreset("dove-purple");
  EXPECT_EQ(purple.b, preset.b);
  EXPECT_EQ(purple.mu, preset.mu);
  EXPECT_FLOAT_EQ(purple.height, 0.55f);
  EXPECT_FLOAT_EQ(purple.filmIOR.a, 1.56f);
  EXPECT_THROW(barbuleParametersWith({}, {{"preset", "dove-blue"}}), InputError);
}

// As spreadsheet programs save CSV: "the header has no column 'theta_i'".
TEST(SpectraFit, TheCSVMayStartWithAByteOrderMark) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("columba_bom_" + std::to_string(getpid()) + ".csv")).string();
  std::ofstream(path) << "\xEF\xBB\xBFtheta_i,phi_i,theta_o,phi_o,wavelength_nm,reflectance\n10,0,10,180,500,0.25\n";
  std::vector<SpectraSample> samples = readSpectraCSV(path);
  std::filesystem::remove(path);
  ASSERT_EQ(samples.size(), 1u);
  EXPECT_EQ(samples[0].thetaI, 10.0f);
  EXPECT_EQ(samples[0].reflectance, 0.25f);
}

TEST(LossProfile, BothMinimaOfATwoMinimumLossAreReportedAndTheIntervalCoversBoth) {
  // A loss with two equal dips, at 0.42 and 0.60 (as a film thickness whose interference orders
  // the data cannot tell apart): whichever the optimiser finds, both are solutions.
  auto loss = [](const std::vector<double>& x) {
    const double d = std::min(std::abs(x[0] - 0.42), std::abs(x[0] - 0.60));
    return LossValue{0.01 + d * d, 1.0};
  };
  FitSettings settings;
  settings.optimizer.maxEvaluations = 60;
  const FitResult r = runFit({parseFitParameter("height=0.4:0.8")}, loss, settings);
  const LossProfile& p = r.profiles[0];
  ASSERT_EQ(p.solutions.size(), 2u);
  EXPECT_NEAR(p.solutions[0].value, 0.42, 0.02);
  EXPECT_NEAR(p.solutions[1].value, 0.60, 0.02);
  EXPECT_LT(p.lower, 0.42);
  EXPECT_GT(p.upper, 0.60);
  EXPECT_FALSE(p.upperAtBound);
  // Each solution's own stretch: where 0.01 + d^2 < 1.1 x the optimum's loss, |d| < 0.032.
  for (const ProfileSolution& s : p.solutions) {
    EXPECT_LT(s.lower, s.value);
    EXPECT_GT(s.upper, s.value);
    EXPECT_NEAR(s.upper - s.lower, 2 * std::sqrt(0.1 * 0.01), 0.03);
  }
  // A single dip gives a single solution.
  auto single = [](const std::vector<double>& x) { return LossValue{0.01 + (x[0] - 0.6) * (x[0] - 0.6), 1.0}; };
  const FitResult one = runFit({parseFitParameter("height=0.4:0.8")}, single, settings);
  EXPECT_EQ(one.profiles[0].solutions.size(), 1u);
}

TEST(FitReport, RecordsValuesIntervalsAndEveryEvaluation) {
  std::vector<SpectraSample> samples;
  for (float lambda = 400.0f; lambda <= 700.0f; lambda += 10.0f)
    samples.push_back({20.0f, 0.0f, 20.0f, 180.0f, lambda, 0.0f});
  std::vector<float> clean = modelSpectra(barbuleParametersWith({{"height", 0.6}}), samples);
  for (size_t i = 0; i < samples.size(); ++i) samples[i].reflectance = 2.0f * clean[i];
  SpectraFitSettings s;
  s.samples = samples;
  s.parameters = {parseFitParameter("height=0.5:0.7")};
  s.fit.optimizer.maxEvaluations = 60;
  SpectraFitResult r = fitSpectra(s);
  nlohmann::json record = fitRecord(r.fit, {{"spectra", "test"}});
  EXPECT_NEAR(record["parameters"][0]["value"].get<double>(), 0.6, 1e-3);
  EXPECT_NEAR(record["scale"].get<double>(), 2.0, 0.01);
  EXPECT_LE(record["parameters"][0]["interval"][0].get<double>(), 0.6);
  EXPECT_GE(record["parameters"][0]["interval"][1].get<double>(), 0.6);
  EXPECT_EQ(record["evaluations"].get<int>(), r.fit.evaluations);
  CsvTable history = historyTable(r.fit);
  EXPECT_EQ(history.rows.size(), size_t(r.fit.evaluations + r.fit.profileEvaluations));
  // The stages are named by the algorithms that ran: the default global one, and Nelder-Mead for
  // one parameter.
  ASSERT_EQ(history.comments.size(), 1u);
  EXPECT_NE(history.comments[0].find("1 global (GN_CRS2_LM), 2 local (LN_NELDERMEAD)"), std::string::npos)
      << history.comments[0];
  s.fit.optimizer.globalAlgorithm = "GN_DIRECT_L";
  s.fit.optimizer.maxEvaluations = 20;
  s.parameters.push_back(parseFitParameter("H=1.0:2.0"));
  const std::string direct = historyTable(fitSpectra(s).fit).comments.at(0);
  EXPECT_NE(direct.find("1 global (GN_DIRECT_L), 2 local (LN_BOBYQA)"), std::string::npos) << direct;
  EXPECT_GT(profilesImage(r.fit).width, 0);
  EXPECT_GT(renderLinePlot(spectraPlot(samples, r.model, r.fit.loss.scale), 1000, 640).width, 0);
  Image target(16, 8);
  target.rgb.assign(target.rgb.size(), 1.0f);
  Image compare = compareImage(target, target, 0.5, std::nullopt);
  EXPECT_GT(compare.width, 3 * 16);
}

}  // namespace
TEST(SpectraFit, APresetIsTheStartOfTheParametersItSets) {
  // A 20-degree mirror spectrum of the purple barbules: with -D preset=dove-purple the fit of
  // their thickness starts at the preset's 0.51 um, not at the middle of the bounds; a START
  // given with the bounds still wins, and a preset value outside them is not used.
  std::vector<SpectraSample> samples;
  for (float lambda = 400.0f; lambda <= 700.0f; lambda += 10.0f) samples.push_back({20, 0, 20, 180, lambda, 0});
  const std::vector<float> values = modelSpectra(barbuleParametersWith({}, {{"preset", "dove-purple"}}), samples);
  for (size_t i = 0; i < samples.size(); ++i) samples[i].reflectance = values[i];
  auto startOf = [&](const std::string& vary) {
    SpectraFitSettings s;
    s.samples = samples;
    s.fixed = {{"preset", "dove-purple"}};
    s.parameters = {parseFitParameter(vary)};
    s.fit.optimizer.maxEvaluations = 20;
    const FitResult r = fitSpectra(s).fit;
    EXPECT_EQ(r.history.front().stage, "start");
    return r.history.front().values[0];
  };
  EXPECT_NEAR(startOf("height=0.4:0.8"), 0.51, 1e-6);
  EXPECT_NEAR(startOf("height=0.4:0.8:0.7"), 0.7, 1e-12);
  EXPECT_NEAR(startOf("height=0.55:0.8"), 0.675, 1e-12);
}

}  // namespace columba
