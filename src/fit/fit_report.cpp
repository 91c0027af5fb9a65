#include "fit/fit_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "plot/canvas.h"
#include "plot/contact_sheet.h"
#include "plot/line_plot.h"

namespace columba {

namespace {

const Vec3 kWhite(1.0f, 1.0f, 1.0f);
const Vec3 kBlack(0.0f, 0.0f, 0.0f);

// Blue (-1), white (0), red (+1), in linear RGB.
Vec3 diverging(float t) {
  t = std::clamp(t, -1.0f, 1.0f);
  const Vec3 end = t < 0.0f ? srgbColour(0.23f, 0.30f, 0.75f) : srgbColour(0.71f, 0.02f, 0.15f);
  const float a = std::abs(t);
  return kWhite * (1.0f - a) + end * a;
}

const std::vector<Vec3>& seriesColours() {
  static const std::vector<Vec3> colours = {srgbColour(0.12f, 0.47f, 0.71f), srgbColour(1.0f, 0.5f, 0.05f),
                                            srgbColour(0.17f, 0.63f, 0.17f), srgbColour(0.84f, 0.15f, 0.16f),
                                            srgbColour(0.58f, 0.40f, 0.74f), srgbColour(0.55f, 0.34f, 0.29f)};
  return colours;
}

bool masked(const std::optional<Image>& mask, int x, int y) {
  if (!mask) return true;
  const float* m = mask->pixel(x, y);
  return std::max({m[0], m[1], m[2]}) >= 0.5f;
}

}  // namespace

nlohmann::json fitRecord(const FitResult& result, const nlohmann::json& settings) {
  nlohmann::json record;
  record["settings"] = settings;
  record["loss"] = result.loss.loss;
  record["scale"] = result.loss.scale;
  record["evaluations"] = result.evaluations;
  record["seconds"] = result.seconds;
  record["seconds_per_evaluation"] = result.seconds / std::max(result.evaluations, 1);
  record["profile_evaluations"] = result.profileEvaluations;
  record["total_seconds"] = result.totalSeconds;
  record["uncertainty"] = fmt::format(
      "1-D slice of the loss through the optimum over each parameter's bounds (other parameters held at their "
      "fitted values): every stretch where the loss stays below (1 + {:g}) x its minimum is a solution, and the "
      "interval spans them all; an end at a bound means the loss never rose that far",
      result.profileRise);
  for (size_t i = 0; i < result.parameters.size(); ++i) {
    const FitParameter& p = result.parameters[i];
    const LossProfile& profile = result.profiles[i];
    nlohmann::json solutions = nlohmann::json::array();
    for (const ProfileSolution& s : profile.solutions)
      solutions.push_back({{"value", s.value}, {"loss", s.loss}, {"interval", {s.lower, s.upper}}});
    record["parameters"].push_back({{"name", p.name},
                                    {"value", result.values[i]},
                                    {"interval", {profile.lower, profile.upper}},
                                    {"interval_reaches_bound", {profile.lowerAtBound, profile.upperAtBound}},
                                    {"solutions", solutions},
                                    {"bounds", {p.lower, p.upper}},
                                    {"start", p.startValue()}});
  }
  return record;
}

CsvTable historyTable(const FitResult& result) {
  CsvTable table;
  table.comments = {
      fmt::format("every evaluation of the loss in order; stage 0 start, 1 global ({}), 2 local ({}), 3 loss profile; "
                  "seconds since the fit began",
                  result.globalAlgorithm, result.localAlgorithm)};
  table.columns = {"evaluation", "stage"};
  for (const FitParameter& p : result.parameters) table.columns.push_back(p.name);
  for (const char* c : {"loss", "scale", "best_loss", "seconds"}) table.columns.push_back(c);
  double best = HUGE_VAL;
  for (const Evaluation& e : result.history) {
    const double stage = e.stage == "start" ? 0 : e.stage == "global" ? 1 : e.stage == "local" ? 2 : 3;
    std::vector<double> row = {double(e.index), stage};
    row.insert(row.end(), e.values.begin(), e.values.end());
    best = std::min(best, e.loss.loss);
    row.insert(row.end(), {e.loss.loss, e.loss.scale, best, e.seconds});
    table.rows.push_back(row);
  }
  return table;
}

std::vector<LinePlot> profilePlots(const FitResult& result) {
  std::vector<LinePlot> plots;
  const double threshold = result.loss.loss * (1.0 + result.profileRise);
  for (size_t i = 0; i < result.parameters.size(); ++i) {
    const FitParameter& p = result.parameters[i];
    const LossProfile& profile = result.profiles[i];
    LinePlot plot;
    plot.title = fmt::format("{} = {:.4g} in [{:.4g}, {:.4g}]", p.name, result.values[i], profile.lower, profile.upper);
    plot.subtitle = fmt::format("loss < (1 + {:g}) x minimum inside the interval (dashed)", result.profileRise);
    plot.xLabel = p.name;
    plot.yLabel = "loss";
    PlotSeries loss{"loss", {}, seriesColours()[0], false};
    for (size_t k = 0; k < profile.values.size(); ++k)
      loss.points.push_back(Vec2(float(profile.values[k]), float(profile.losses[k])));
    const double highest = *std::max_element(profile.losses.begin(), profile.losses.end());
    plot.xMin = float(profile.values.front());
    plot.xMax = float(profile.values.back());
    if (!(plot.xMax > plot.xMin)) plot.xMax = plot.xMin + 1.0f;
    // From just below the minimum, so that a rise of a few per cent is visible.
    plot.yMin = float(result.loss.loss * 0.95);
    plot.yMax = float(std::max(highest, threshold) * 1.02);
    if (!(plot.yMax > plot.yMin)) plot.yMax = plot.yMin + 1.0f;
    PlotSeries level{
        "threshold", {Vec2(plot.xMin, float(threshold)), Vec2(plot.xMax, float(threshold))}, seriesColours()[1], true};
    PlotSeries interval{"interval",
                        {Vec2(float(profile.lower), plot.yMin), Vec2(float(profile.lower), plot.yMax),
                         Vec2(float(profile.upper), plot.yMax), Vec2(float(profile.upper), plot.yMin)},
                        seriesColours()[2],
                        true};
    plot.series = {loss, level, interval};
    plots.push_back(plot);
  }
  return plots;
}

Image profilesImage(const FitResult& result) {
  std::vector<ContactSheetEntry> entries;
  const std::vector<LinePlot> plots = profilePlots(result);
  for (size_t i = 0; i < plots.size(); ++i)
    entries.push_back({renderLinePlot(plots[i], 1000, 640), result.parameters[i].name});
  return makeContactSheet(entries, std::min<int>(2, int(entries.size())), 640, "Loss profiles around the optimum");
}

Image compareImage(const Image& target, const Image& render, double scale, const std::optional<Image>& mask) {
  // Both images shown at the same exposure: the target's 99.5th percentile brightest channel is 1.
  std::vector<float> brightest;
  float largestDifference = 0.0f;
  Image difference(target.width, target.height);
  std::vector<float> signedMean(size_t(target.width) * target.height, 0.0f);
  for (int y = 0; y < target.height; ++y)
    for (int x = 0; x < target.width; ++x) {
      if (!masked(mask, x, y)) continue;
      const float* t = target.pixel(x, y);
      const float* r = render.pixel(x, y);
      brightest.push_back(std::max({t[0], t[1], t[2]}));
      float d = 0.0f;
      for (int c = 0; c < 3; ++c) d += (float(scale) * r[c] - t[c]) / 3.0f;
      if (std::isfinite(d)) largestDifference = std::max(largestDifference, std::abs(d));
      signedMean[size_t(y) * target.width + x] = d;
    }
  float white = 1.0f;
  if (!brightest.empty()) {
    size_t k = std::min(brightest.size() - 1, size_t(0.995 * double(brightest.size())));
    std::nth_element(brightest.begin(), brightest.begin() + long(k), brightest.end());
    if (brightest[k] > 0.0f) white = brightest[k];
  }
  if (!(largestDifference > 0.0f)) largestDifference = 1.0f;
  Image shownTarget = target, shownRender = render;
  for (float& v : shownTarget.rgb) v /= white;
  for (float& v : shownRender.rgb) v = float(scale) * v / white;
  for (int y = 0; y < target.height; ++y)
    for (int x = 0; x < target.width; ++x) {
      const Vec3 c = masked(mask, x, y) ? diverging(signedMean[size_t(y) * target.width + x] / largestDifference)
                                        : Vec3(0.2f, 0.2f, 0.2f);
      float* p = difference.pixel(x, y);
      p[0] = c.x, p[1] = c.y, p[2] = c.z;
    }

  const int panel = std::max(256, target.width);
  const int panelHeight = std::max(1, int(std::lround(double(panel) * target.height / target.width)));
  const int margin = 16, titleHeight = 30, barHeight = 70;
  Canvas canvas(3 * panel + 4 * margin, panelHeight + titleHeight + barHeight + 2 * margin, kWhite);
  const std::vector<std::pair<std::string, const Image*>> panels = {
      {"target", &shownTarget},
      {fmt::format("fitted render x {:.4g}", scale), &shownRender},
      {"fit - target, RGB mean", &difference}};
  for (size_t i = 0; i < panels.size(); ++i) {
    const int x = margin + int(i) * (panel + margin);
    canvas.text(float(x), float(margin), panels[i].first, kBlack);
    canvas.drawImage(x, margin + titleHeight, resizeImage(*panels[i].second, panel, panelHeight));
  }
  // The colour bar under the difference, from -D to +D.
  const float barX = float(margin + 2 * (panel + margin)), barY = float(margin + titleHeight + panelHeight + 12);
  for (int k = 0; k < panel; ++k) {
    const float t = 2.0f * (float(k) + 0.5f) / float(panel) - 1.0f;
    canvas.fillRect(barX + float(k), barY, barX + float(k + 1), barY + 16.0f, diverging(t));
  }
  const std::vector<std::pair<float, std::string>> labels = {
      {0.0f, fmt::format("{:.3g}", -largestDifference)}, {0.5f, "0"}, {1.0f, fmt::format("{:.3g}", largestDifference)}};
  // Left-aligned at the bar's start, centred in its middle, right-aligned at its end.
  for (const auto& [at, label] : labels)
    canvas.text(barX + at * (float(panel) - Canvas::textWidth(label)), barY + 22.0f, label, kBlack);
  canvas.text(float(margin), barY + 4.0f, "display: the target's 99.5th percentile is white", kBlack);
  canvas.text(float(margin), barY + 26.0f, "difference: in the target's units", kBlack);
  return canvas.image();
}

LinePlot spectraPlot(const std::vector<SpectraSample>& samples, const std::vector<float>& model, double scale) {
  LinePlot plot;
  plot.title = "Reflectance spectra: measured (points) and fitted (lines)";
  plot.subtitle = fmt::format("reflectance factor pi f | fitted scale {:.4g}", scale);
  plot.xLabel = "wavelength (nm)";
  plot.yLabel = "reflectance factor";
  plot.xMin = 1e9f, plot.xMax = -1e9f, plot.yMin = 0.0f, plot.yMax = 0.0f;
  std::vector<PlotSeries> measured, fitted;
  for (size_t i = 0; i < samples.size(); ++i) {
    const SpectraSample& s = samples[i];
    if (i == 0 || s.thetaI != samples[i - 1].thetaI || s.phiI != samples[i - 1].phiI ||
        s.thetaO != samples[i - 1].thetaO || s.phiO != samples[i - 1].phiO) {
      const Vec3 colour = seriesColours()[measured.size() % seriesColours().size()];
      const std::string label = fmt::format("in {:g}/{:g}, out {:g}/{:g} deg", s.thetaI, s.phiI, s.thetaO, s.phiO);
      measured.push_back({label + " measured", {}, colour, false, true});
      fitted.push_back({label + " fitted", {}, colour, false, false});
    }
    const float fit = float(scale) * model[i];
    measured.back().points.push_back(Vec2(s.wavelength, s.reflectance));
    fitted.back().points.push_back(Vec2(s.wavelength, fit));
    plot.xMin = std::min(plot.xMin, s.wavelength);
    plot.xMax = std::max(plot.xMax, s.wavelength);
    plot.yMax = std::max({plot.yMax, s.reflectance, fit});
  }
  plot.yMax *= 1.05f;
  if (!(plot.yMax > 0.0f)) plot.yMax = 1.0f;
  if (!(plot.xMax > plot.xMin)) plot.xMax = plot.xMin + 1.0f;
  for (size_t k = 0; k < measured.size(); ++k) {
    plot.series.push_back(measured[k]);
    plot.series.push_back(fitted[k]);
  }
  return plot;
}

}  // namespace columba
