#include "app/bsdf_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <limits>

#include "app/scene_options.h"
#include "barbule/measurement.h"
#include "barbule/model.h"
#include "barbule/parameter_reader.h"
#include "bsdfs/barbulearms.h"
#include "core/illuminant.h"
#include "core/version.h"
#include "io/data_files.h"
#include "io/output_directory.h"
#include "plot/canvas.h"
#include "plot/hemisphere_chart.h"
#include "plot/line_plot.h"
#include "scene/xml_values.h"
#include "vision/colour_distance.h"
#include "vision/colour_summary.h"
#include "vision/observer_table.h"

namespace columba {

namespace {
namespace fs = std::filesystem;

// `columba bsdf` as a virtual goniometer: the barbule BSDF measured as instruments measure it,
// for a list of light polar angles at one azimuth, with every plot's data beside it.
struct BSDFOptions {
  BarbuleParameters params;
  std::string preset, filmIOR, melaninFile, layers;
  float cauchyA = std::numeric_limits<float>::quiet_NaN(), cauchyB = 0.0f;  // NaN: not given
  std::vector<float> angles{0.0f, 20.0f, 40.0f, 60.0f};                     // light polar angles, degrees
  float phiDegrees = 0.0f;
  std::vector<std::string> modes{"hemisphere", "spectra"};
  bool spectral = false;
  int bins = 16;
  std::string spectralRange;  // LO:HI nm; "": 300-830, the range the model is evaluated over
  int resolution = 256;
  std::string outputDir = ".";
  std::string observer;  // a bird's: the specular spectra's cone catches and colour distances
  // Barbules of flat arms (barbulearms) with these tilts instead of the ellipse model.
  std::string armTilts;
  std::shared_ptr<const BarbuleArmsBSDF> arms;
};

const Vec3 kSeriesColours[] = {srgbColour(0.10f, 0.35f, 0.80f), srgbColour(0.10f, 0.60f, 0.30f),
                               srgbColour(0.85f, 0.55f, 0.05f), srgbColour(0.80f, 0.15f, 0.15f),
                               srgbColour(0.55f, 0.20f, 0.70f), srgbColour(0.35f, 0.35f, 0.35f)};
Vec3 seriesColour(size_t i) { return kSeriesColours[i % std::size(kSeriesColours)]; }

// Everything the run measured with, for file headers, titles and the JSON record.
std::string describeParameters(const BSDFOptions& o) {
  const BarbuleParameters& p = o.params;
  std::string film =
      o.filmIOR.empty()
          ? (std::isnan(o.cauchyA) ? "keratin" : fmt::format("Cauchy {} + {}/lambda^2", o.cauchyA, o.cauchyB))
          : o.filmIOR;
  if (o.arms)
    return fmt::format(
               "barbulearms | arm_tilts {} deg | b {} | profile_exponent {} | mu {} rad | H {:.4g} | height {} "
               "um | film_ior {} | ext_ior {}",
               o.armTilts, p.b, p.profileExponent, p.mu, p.H, p.height, film, p.extIOR) +
           (o.layers.empty() ? "" : " | layers " + o.layers);
  return fmt::format(
             "b {} | phi_0 {} rad | phi_1 {} rad | mu {} rad | H {} | height {} um | film_ior {} | ext_ior {} | "
             "melanin {}{}",
             p.b, p.phi0, p.phi1, p.mu, p.H, p.height, film, p.extIOR,
             o.melaninFile.empty() ? "embedded table" : o.melaninFile,
             o.preset.empty() ? "" : " | preset " + o.preset) +
         (o.layers.empty() ? "" : " | layers " + o.layers) +
         (p.profileExponent == 2.0f ? "" : fmt::format(" | profile_exponent {}", p.profileExponent));
}

std::string angleList(const std::vector<float>& angles) {
  std::string s;
  for (float a : angles) s += (s.empty() ? "" : ", ") + fmt::format("{:g}", a);
  return s;
}

// The light's direction for polar angle `thetaDeg` at the run's azimuth.
Vec3 lightDirection(const BSDFOptions& o, float thetaDeg) {
  return directionFromAngles(degToRad(thetaDeg), degToRad(o.phiDegrees));
}

std::string angleTag(float thetaDeg) { return fmt::format("theta{:g}", thetaDeg); }

// The plot as PNG, and as SVG and PDF beside it for papers.
void writePlot(const fs::path& path, const LinePlot& plot, std::vector<std::string>& written) {
  for (const char* extension : {".png", ".svg", ".pdf"}) {
    fs::path file = path;
    file.replace_extension(extension);
    writeLinePlot(file.string(), plot, 1000, 640);
    written.push_back(file.string());
  }
}

void writeTable(const fs::path& path, const CsvTable& table, std::vector<std::string>& written) {
  writeCSV(path.string(), table);
  written.push_back(path.string());
}

// The bins of --spectral: --spectral-range, or the whole range the model is evaluated over.
std::pair<float, float> bsdfSpectralRange(const BSDFOptions& o) {
  return o.spectralRange.empty() ? std::pair{kSpectralMin, kLambdaMax} : parseSpectralRange(o.spectralRange);
}

void measureHemispheres(const BarbuleLobeSource& model, const BSDFOptions& o, const fs::path& dir,
                        std::vector<std::string>& written) {
  for (float angle : o.angles) {
    Vec3 light = lightDirection(o, angle);
    Image image = scatterometerImage(model, light, o.resolution);
    const auto [lo, hi] = bsdfSpectralRange(o);
    if (o.spectral) image.spectral = spectralScatterometerBands(model, light, o.resolution, o.bins, lo, hi);
    ImageMetadata metadata = {
        {"Measurement",
         "scatterometer image: f(light, camera) |cos theta_camera| per steradian under a D65 beam of "
         "unit luminance (RGB); spectral channels: f |cos theta_camera| per steradian, bin means"},
        {"Light", fmt::format("theta {:g} deg, phi {:g} deg", angle, o.phiDegrees)},
        {"Parameters", describeParameters(o)}};
    if (o.spectral) {
      metadata.emplace_back("Spectral channels", fmt::format("{} bins of {:g} nm over {:g}-{:g} nm (S0.<centre>nm)",
                                                             o.bins, (hi - lo) / float(o.bins), lo, hi));
    }
    fs::path exr = dir / ("bsdf_hemisphere_" + angleTag(angle) + ".exr");
    writeEXR(exr.string(), image, metadata);
    // The PNG is the chart a person reads; the EXR holds the data.
    HemisphereChart chart{fmt::format("Scatterometer, light at {:g} deg", angle),
                          fmt::format("light phi {:g} deg | f cos(theta_camera) per sr under a D65 beam | {}",
                                      o.phiDegrees, describeParameters(o))};
    chart.lightTheta = degToRad(angle);
    chart.lightPhi = degToRad(o.phiDegrees);
    chart.valueLabel = "luminance";
    written.push_back(exr.string());
    for (const char* extension : {".png", ".svg", ".pdf"}) {  // PNG to look at, SVG and PDF for papers
      fs::path file = dir / ("bsdf_hemisphere_" + angleTag(angle) + extension);
      writeHemisphereChart(file.string(), image, chart, metadata);
      written.push_back(file.string());
    }
  }
}

// A plot against wavelength over the light angles, and its table with a wavelength column.
struct SpectralFigure {
  LinePlot plot;
  CsvTable table;
};
SpectralFigure spectralFigure(const BSDFOptions& o, const std::vector<float>& lambdas, const std::string& title,
                              const std::string& yLabel, const std::string& quantity) {
  SpectralFigure f;
  f.plot.title = title;
  f.plot.subtitle =
      fmt::format("light theta {} deg, phi {:g} deg | {}", angleList(o.angles), o.phiDegrees, describeParameters(o));
  f.plot.xLabel = "wavelength (nm)";
  f.plot.yLabel = yLabel;
  f.plot.xMin = kSpectralMin;
  f.plot.xMax = kLambdaMax;
  f.table = {{quantity, describeParameters(o)}, {"wavelength_nm"}, std::vector<std::vector<double>>(lambdas.size())};
  // Spectra start at 300 nm, below the range keratin's index was measured in (docs/vision.md).
  if (lambdas.front() < 400.0f && o.filmIOR.empty() && std::isnan(o.cauchyA))
    f.table.comments.push_back(
        "below 400 nm keratin's index extrapolates the Cauchy fit of Leertouwer, Wilts & Stavenga (2011), "
        "measured in the visible");
  for (size_t i = 0; i < lambdas.size(); ++i) f.table.rows[i].push_back(lambdas[i]);
  return f;
}

// Directional reflectance (albedo) of R and TRT per light angle.
void measureAlbedo(const BarbuleLobeSource& model, const BSDFOptions& o, const fs::path& dir, nlohmann::json& record,
                   std::vector<std::string>& written) {
  const std::vector<float> lambdas = wavelengthGrid(kSpectralMin, 1.0f);
  auto [plot, table] = spectralFigure(
      o, lambdas, "Directional reflectance of the barbule lobes", "directional reflectance (R solid, TRT dashed)",
      "directional reflectance (albedo) of the R and TRT lobes: the integral over "
      "outgoing directions of f |cos theta_o| (dimensionless), to 0.1 % (docs/model.md, "
      "Measurements)");
  float peak = 0.0f;
  fmt::print("directional reflectance (albedo), light azimuth {:g} deg\n", o.phiDegrees);
  fmt::print("light theta (deg)  mean R    mean TRT  coverage  R peaks (nm, 1 nm grid)\n");
  for (size_t a = 0; a < o.angles.size(); ++a) {
    Vec3 light = lightDirection(o, o.angles[a]);
    LobeSpectra lr = lobeReflectance(model, light, lambdas);
    PlotSeries r{fmt::format("R {:g} deg", o.angles[a]), {}, seriesColour(a)};
    PlotSeries t{fmt::format("TRT {:g} deg", o.angles[a]), {}, seriesColour(a), true};
    double meanR = 0, meanT = 0;
    for (size_t i = 0; i < lambdas.size(); ++i) {
      r.points.push_back(Vec2(lambdas[i], lr.reflection[i]));
      t.points.push_back(Vec2(lambdas[i], lr.trt[i]));
      table.rows[i].push_back(lr.reflection[i]);
      table.rows[i].push_back(lr.trt[i]);
      peak = std::max(peak, std::max(lr.reflection[i], lr.trt[i]));
      meanR += lr.reflection[i] / lambdas.size();
      meanT += lr.trt[i] / lambdas.size();
    }
    table.columns.push_back(fmt::format("R_theta{:g}", o.angles[a]));
    table.columns.push_back(fmt::format("TRT_theta{:g}", o.angles[a]));
    std::vector<float> peaks = peakWavelengths(lambdas, lr.reflection);
    float coverage = model.coverage(light);
    fmt::print("{:17g}  {:7.4f}   {:7.4f}   {:7.3f}   {}\n", o.angles[a], meanR, meanT, coverage,
               fmt::join(peaks, " "));
    record["spectra"].push_back({{"light_theta_deg", o.angles[a]},
                                 {"mean_R", meanR},
                                 {"mean_TRT", meanT},
                                 {"coverage", coverage},
                                 {"R_peaks_nm", peaks}});
    plot.series.push_back(std::move(r));
    plot.series.push_back(std::move(t));
  }
  plot.yMax = std::max(0.05f, peak * 1.1f);
  writePlot(dir / "bsdf_spectra.png", plot, written);
  writeTable(dir / "bsdf_spectra.csv", table, written);
}

// The total specular spectra in the layout R's pavo reads (as.rspec of read.csv): a `wl` column of
// 1 nm steps over 300-700 nm, then one column a light angle; no comment lines.
CsvTable pavoTable(const BSDFOptions& o, const std::vector<float>& lambdas,
                   const std::vector<std::vector<float>>& totals) {
  CsvTable table{{}, {"wl"}, {}};
  for (float angle : o.angles) table.columns.push_back(fmt::format("total_theta{:g}", angle));
  for (size_t i = 0; i < lambdas.size() && lambdas[i] <= 700.0f; ++i) {
    table.rows.push_back({lambdas[i]});
    for (const std::vector<float>& total : totals) table.rows.back().push_back(total[i]);
  }
  return table;
}

// Each light angle's specular spectrum as a bird sees it lit by D65: its cones' quantum catches
// adapted to a white under D65 (pavo's vismodel with illum = "D65", vonkries = TRUE), their
// relative catches, and the receptor-noise-limited distance (JND) from the first angle's colour.
void measureConeCatches(const BSDFOptions& o, const std::vector<float>& lambdas,
                        const std::vector<std::vector<float>>& totals, const fs::path& dir, nlohmann::json& record,
                        std::vector<std::string>& written) {
  const Observer observer = observerNamedOrTabulated(o.observer);
  const std::vector<float> illuminant = tabulateOnGrid(observer.grid, [](double l) { return d65(float(l)); });
  CsvTable table{{fmt::format("cone catches of the specular spectra (total) for the {} observer, lit by D65 and "
                              "adapted to a white under it (von Kries); relative catches sum to 1; dS: "
                              "receptor-noise-limited distance from the first light angle, in JND",
                              observer.name)},
                 {"light_theta_deg"},
                 {}};
  for (const std::string& c : observer.channels) table.columns.push_back(c);
  for (const std::string& c : observer.channels) table.columns.push_back("relative_" + c);
  table.columns.push_back("dS_jnd");
  fmt::print("cone catches ({}, D65, von Kries): light theta (deg), {}, dS from {:g} deg (JND)\n", observer.name,
             fmt::join(observer.channels, ", "), o.angles.front());
  std::vector<ConeCatches> catches;
  for (size_t a = 0; a < totals.size(); ++a) {
    std::vector<float> reflectance = tabulateOnGrid(observer.grid, [&](double l) {
      const size_t i = size_t(std::lround(l - double(lambdas.front())));
      return i < lambdas.size() ? double(totals[a][i]) : 0.0;
    });
    catches.push_back(adaptedQuantumCatches(observer, reflectance, illuminant));
    const std::vector<double>& q = catches.back().chromatic;
    const std::vector<double> relative = relativeCatches(q);
    const double dS = chromaticDistance(observer, catches.front(), catches.back());
    table.rows.push_back({o.angles[a]});
    table.rows.back().insert(table.rows.back().end(), q.begin(), q.end());
    table.rows.back().insert(table.rows.back().end(), relative.begin(), relative.end());
    table.rows.back().push_back(dS);
    fmt::print("{:17g}  {:.4f}  dS {:.2f}\n", o.angles[a], fmt::join(q, " "), dS);
    record["cone_catches"].push_back({{"light_theta_deg", o.angles[a]}, {"catches", q}, {"dS_jnd", dS}});
  }
  writeTable(dir / "bsdf_specular_catches.csv", table, written);
}

// Reflectance factor in the mirror direction of each light angle: a microspectrophotometer.
void measureSpecular(const BarbuleLobeSource& model, const BSDFOptions& o, const fs::path& dir, nlohmann::json& record,
                     std::vector<std::string>& written) {
  const std::vector<float> lambdas = wavelengthGrid(kSpectralMin, 1.0f);
  auto [plot, table] = spectralFigure(o, lambdas, "Reflectance factor pi f in the mirror direction",
                                      "reflectance factor in the mirror direction (total solid, R dashed)",
                                      "reflectance factor pi f(light, mirror direction) of the R and TRT lobes and "
                                      "their sum, relative to a white diffuse standard (dimensionless)");
  float peak = 0.0f;
  std::vector<std::vector<float>> totals;  // per light angle
  std::vector<std::string> summaries;      // the rows of pavo's summary variables
  fmt::print("specular reflectance factor (pi f in the mirror direction), light azimuth {:g} deg\n", o.phiDegrees);
  fmt::print("light theta (deg)  total peaks (nm)   R peaks (nm)   TRT peaks (nm)   max total\n");
  for (size_t a = 0; a < o.angles.size(); ++a) {
    LobeSpectra s = specularSpectra(model, lightDirection(o, o.angles[a]), lambdas);
    std::vector<float> total(lambdas.size());
    PlotSeries sum{fmt::format("total {:g} deg", o.angles[a]), {}, seriesColour(a)};
    PlotSeries r{fmt::format("R {:g} deg", o.angles[a]), {}, seriesColour(a), true};
    float largest = 0.0f;
    for (size_t i = 0; i < lambdas.size(); ++i) {
      total[i] = s.reflection[i] + s.trt[i];
      sum.points.push_back(Vec2(lambdas[i], total[i]));
      r.points.push_back(Vec2(lambdas[i], s.reflection[i]));
      table.rows[i].insert(table.rows[i].end(), {s.reflection[i], s.trt[i], total[i]});
      largest = std::max(largest, total[i]);
    }
    peak = std::max(peak, largest);
    for (const char* lobe : {"R", "TRT", "total"})
      table.columns.push_back(fmt::format("{}_theta{:g}", lobe, o.angles[a]));
    totals.push_back(total);
    std::vector<float> totalPeaks = peakWavelengths(lambdas, total), rPeaks = peakWavelengths(lambdas, s.reflection),
                       trtPeaks = peakWavelengths(lambdas, s.trt);
    fmt::print("{:17g}  {:<18} {:<14} {:<16} {:.4f}\n", o.angles[a], fmt::format("{}", fmt::join(totalPeaks, " ")),
               fmt::format("{}", fmt::join(rPeaks, " ")), fmt::format("{}", fmt::join(trtPeaks, " ")), largest);
    const ColourSummary summary = colourSummary(lambdas, total),
                        visible = colourSummary(lambdas, total, 400.0f, 700.0f);
    summaries.push_back(fmt::format("{:17g}  {:<8.2f} {:<8.3f} {:<8g} {:g}", o.angles[a], summary.B1, summary.S8,
                                    summary.H1, visible.H1));
    record["specular"].push_back({{"light_theta_deg", o.angles[a]},
                                  {"total_peaks_nm", totalPeaks},
                                  {"R_peaks_nm", rPeaks},
                                  {"TRT_peaks_nm", trtPeaks},
                                  {"max_total", largest},
                                  {"visible_peak_nm", visible.H1},
                                  {"pavo_summary",
                                   {{"range_nm", {300, 700}},
                                    {"B1", summary.B1},
                                    {"B2", summary.B2},
                                    {"S8", summary.S8},
                                    {"H1_nm", summary.H1}}}});
    plot.series.push_back(std::move(sum));
    plot.series.push_back(std::move(r));
  }
  // Every local maximum above is an interference order; the colour's summary is pavo's.
  fmt::print(
      "colour summary of the total, pavo's summary.rspec over 300-700 nm (Montgomerie 2006): B1 the sum at 1 nm, S8 "
      "(max - min) / mean, H1 the wavelength of the maximum; and the maximum over 400-700 nm\n"
      "light theta (deg)  B1       S8       H1 (nm)  400-700 nm peak (nm)\n{}\n",
      fmt::join(summaries, "\n"));
  plot.yMax = std::max(0.05f, peak * 1.1f);
  writePlot(dir / "bsdf_specular.png", plot, written);
  writeTable(dir / "bsdf_specular.csv", table, written);
  writeTable(dir / "bsdf_specular_pavo.csv", pavoTable(o, lambdas, totals), written);
  if (!o.observer.empty()) measureConeCatches(o, lambdas, totals, dir, record, written);
}

// In-plane slices of the scatterometer quantity at a few wavelengths and as RGB.
void measurePlane(const BarbuleLobeSource& model, const BSDFOptions& o, const fs::path& dir,
                  std::vector<std::string>& written) {
  const std::vector<float> shown = {450.0f, 550.0f, 650.0f};
  const std::vector<float> lambdas = wavelengthGrid(kLambdaMin, 5.0f);
  std::vector<float> thetaO;
  for (float t = -89.5f; t <= 89.5f; t += 0.5f) thetaO.push_back(degToRad(t));
  CsvTable table{{"in-plane scatterometer quantity f(light, omega_o) |cos theta_o| (1/sr, R + TRT); theta_o signed, "
                  "positive toward the light's azimuth (the mirror direction is at -theta_light); RGB under a D65 "
                  "beam of unit luminance",
                  describeParameters(o)},
                 {"light_theta_deg", "theta_o_deg", "f_cos_450nm", "f_cos_550nm", "f_cos_650nm", "R", "G", "B"},
                 {}};
  for (float angle : o.angles) {
    Vec3 light = lightDirection(o, angle);
    PlaneSlice spectral = planeSlice(model, light, degToRad(o.phiDegrees), thetaO, lambdas);
    PlaneSlice lines = planeSlice(model, light, degToRad(o.phiDegrees), thetaO, shown);
    std::vector<Vec3> rgb = sliceRGB(spectral);
    LinePlot plot;
    plot.title = fmt::format("In-plane slice, light at theta {:g} deg", angle);
    plot.subtitle = fmt::format("light phi {:g} deg | {}", o.phiDegrees, describeParameters(o));
    plot.xLabel = "outgoing angle theta_o (deg; mirror direction at -theta_light)";
    plot.yLabel = "f |cos theta_o| (1/sr): 450/550/650 nm solid, RGB dashed";
    plot.xMin = -90.0f;
    plot.xMax = 90.0f;
    const Vec3 lineColours[] = {srgbColour(0.2f, 0.3f, 0.9f), srgbColour(0.1f, 0.6f, 0.2f),
                                srgbColour(0.85f, 0.2f, 0.1f)};
    float peak = 0.0f;
    for (size_t k = 0; k < shown.size(); ++k) {
      PlotSeries s{fmt::format("{:g} nm", shown[k]), {}, lineColours[k]};
      for (size_t a = 0; a < thetaO.size(); ++a) {
        s.points.push_back(Vec2(radToDeg(thetaO[a]), lines.values[a][k]));
        peak = std::max(peak, lines.values[a][k]);
      }
      plot.series.push_back(std::move(s));
    }
    const char* channels[] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
      PlotSeries s{std::string("RGB ") + channels[c], {}, lineColours[2 - c], true};
      for (size_t a = 0; a < thetaO.size(); ++a) {
        s.points.push_back(Vec2(radToDeg(thetaO[a]), rgb[a][c]));
        peak = std::max(peak, rgb[a][c]);
      }
      plot.series.push_back(std::move(s));
    }
    plot.yMax = std::max(1e-3f, peak * 1.1f);
    writePlot(dir / ("bsdf_plane_" + angleTag(angle) + ".png"), plot, written);
    for (size_t a = 0; a < thetaO.size(); ++a)
      table.rows.push_back({angle, radToDeg(thetaO[a]), lines.values[a][0], lines.values[a][1], lines.values[a][2],
                            rgb[a].x, rgb[a].y, rgb[a].z});
  }
  writeTable(dir / "bsdf_plane.csv", table, written);
}

// A float as the decimal its shortest representation writes (0.58, not 0.5799999833).
double decimal(float x) { return std::stod(fmt::format("{}", x)); }

nlohmann::json parameterRecord(const BSDFOptions& o) {
  const BarbuleParameters& p = o.params;
  nlohmann::json j = {{"b", decimal(p.b)},
                      {"mu_rad", decimal(p.mu)},
                      {"H", decimal(p.H)},
                      {"height_um", decimal(p.height)},
                      {"ext_ior", decimal(p.extIOR)},
                      {"profile_exponent", decimal(p.profileExponent)}};
  if (o.arms) {
    j["bsdf"] = "barbulearms";
    j["arm_tilts_deg"] = o.armTilts;
  } else {
    j["phi_0_rad"] = decimal(p.phi0);
    j["phi_1_rad"] = decimal(p.phi1);
  }
  if (!o.preset.empty()) j["preset"] = o.preset;
  if (!o.filmIOR.empty())
    j["film_ior"] = o.filmIOR;
  else if (!std::isnan(o.cauchyA))
    j["film_cauchy"] = {{"a", decimal(o.cauchyA)}, {"b_nm2", decimal(o.cauchyB)}};
  else
    j["film_ior"] = "keratin";
  if (!o.arms) j["melanin"] = o.melaninFile.empty() ? "embedded table" : o.melaninFile;
  if (!o.layers.empty()) j["layers"] = o.layers;
  return j;
}

void runBSDF(const BSDFOptions& o) {
  checkOutputDirectory(o.outputDir, o.outputDir);
  const fs::path dir(o.outputDir);
  std::optional<BarbuleModel> ellipse;
  if (!o.arms) ellipse.emplace(o.params);
  const BarbuleLobeSource& model = o.arms ? static_cast<const BarbuleLobeSource&>(*o.arms) : *ellipse;
  makeOutputDirectory(o.outputDir, o.outputDir);
  fmt::print("barbule BSDF: {}\n", describeParameters(o));
  if (o.arms) fmt::print("barbulearms has no TRT lobe: its TRT columns are 0\n");
  // Flat faces: a point value where a face's normal is the half vector is a spike of the
  // singular normal density, not a reading; the albedo integrates it.
  const bool pointValues = std::any_of(o.modes.begin(), o.modes.end(), [](const std::string& m) {
    return m == "hemisphere" || m == "specular" || m == "plane";
  });
  if (pointValues && o.params.profileExponent > 2.0f)
    fmt::print(stderr,
               "warning: --profile-exponent {:g}: above 2 the normal density is infinite at each flat face's own "
               "normal (integrable; docs/model.md, \"Cross-sections beyond the ellipse\"), so hemisphere, specular "
               "and plane values whose half vector is that normal are spikes, not readings; --mode spectra "
               "integrates them\n",
               o.params.profileExponent);
  nlohmann::json record = {{"columba_version", kColumbaVersion},
                           {"parameters", parameterRecord(o)},
                           {"light_theta_deg", o.angles},
                           {"light_phi_deg", o.phiDegrees},
                           {"modes", o.modes},
                           {"resolution", o.resolution}};
  if (o.spectral) {
    const auto [lo, hi] = bsdfSpectralRange(o);
    record["spectral_bins"] = {{"count", o.bins}, {"from_nm", lo}, {"to_nm", hi}};
  }
  std::vector<std::string> written;
  for (const std::string& mode : o.modes) {
    if (mode == "hemisphere")
      measureHemispheres(model, o, dir, written);
    else if (mode == "spectra")
      measureAlbedo(model, o, dir, record, written);
    else if (mode == "specular")
      measureSpecular(model, o, dir, record, written);
    else if (mode == "plane")
      measurePlane(model, o, dir, written);
  }
  record["outputs"] = written;
  writeJSON((dir / "bsdf.json").string(), record);
  written.push_back((dir / "bsdf.json").string());
  fmt::print("wrote {}\n", fmt::join(written, ", "));
}

// The option that gives a barbule parameter: --film-ior for film_ior, but --phi_0 as the paper
// writes phi_0.
std::string optionFor(const std::string& parameter) {
  std::string option = parameter;
  if (option.rfind("phi_", 0) != 0) std::replace(option.begin(), option.end(), '_', '-');
  return "--" + option;
}

// The parameters as the options give them, read as a scene's <bsdf type="barbulebsdf"> is, or with
// --arm-tilts as its <bsdf type="barbulearms">.
void resolveParameters(BSDFOptions& o, const CLI::App& cmd, const BarbuleParameters& given) {
  Properties props;
  props.tag = "bsdf";
  props.type = o.armTilts.empty() ? "barbulebsdf" : "barbulearms";
  props.nameParameter = optionFor;
  auto take = [&](const char* parameter, float value) {
    if (cmd.count(optionFor(parameter)) > 0) props.setFloat(parameter, value);
  };
  if (!o.armTilts.empty()) {
    for (const char* option : {"--preset", "--phi_0", "--phi_1", "--melanin"})
      if (cmd.count(option) > 0)
        throw CLI::ValidationError(option,
                                   "has no effect on barbules of arms (--arm-tilts): they have no arc, preset "
                                   "or melanin layer");
    props.setString("arm_tilts", o.armTilts);
  }
  if (!o.preset.empty()) props.setString("preset", o.preset);
  take("b", given.b);
  take("phi_0", given.phi0);
  take("phi_1", given.phi1);
  take("mu", given.mu);
  take("H", given.H);
  take("profile_exponent", given.profileExponent);
  take("height", given.height);
  take("ext_ior", given.extIOR);
  take("film_cauchy_a", o.cauchyA);
  take("film_cauchy_b", o.cauchyB);
  if (!o.filmIOR.empty()) props.setString("film_ior", o.filmIOR);
  if (!o.layers.empty()) props.setString("layers", o.layers);
  if (!o.melaninFile.empty()) {
    GivenSpectrum melanin = readSpectrumFile(o.melaninFile, "--melanin", SourceLocation{o.melaninFile, 0});
    props.setSpectrum("melanin", melanin.distribution, melanin.lowest);
  }
  if (!o.armTilts.empty()) {
    o.arms = std::static_pointer_cast<const BarbuleArmsBSDF>(makeBarbuleArmsBSDF(props));
    o.params = o.arms->parameters();
    return;
  }
  std::optional<BarbuleParameterProblem> odd;
  o.params = readBarbuleParameters(props, odd);
  if (odd) fmt::print(stderr, "warning: {}: {}\n", optionFor(odd->parameter), odd->message);
}
}  // namespace

void addBSDFCommand(CLI::App& app) {
  auto o = std::make_shared<BSDFOptions>();
  auto given = std::make_shared<BarbuleParameters>();
  CLI::App* cmd = app.add_subcommand(
      "bsdf",
      "Measure the barbule BSDF as a virtual goniometer: scatterometer images, specular and albedo spectra, "
      "in-plane slices (plots with CSV data and a JSON record)");
  cmd->add_option("--preset", o->preset, "Barbule preset: " + barbulePresetNames() + " (options below override it)");
  cmd->add_option("--b", given->b, "Cross-section semi-axis along the vane normal (default 0.25)");
  cmd->add_option("--phi_0", given->phi0, "Start of the reflective arc, rad (default -0.37)");
  cmd->add_option("--phi_1", given->phi1, "End of the reflective arc, rad (default 2.64)");
  cmd->add_option("--mu", given->mu, "Tilt of the cross-section, rad (default -0.35)");
  cmd->add_option("--H", given->H, "Barbule spacing (default 1.25)");
  cmd->add_option("--profile-exponent", given->profileExponent,
                  "Cross-section superellipse exponent, 2 (the ellipse, default) to 16 (a rounded rectangle)");
  cmd->add_option("--height", given->height, "Keratin cortex thickness, um (default 0.6)");
  cmd->add_option("--film-ior", o->filmIOR, "Film index: keratin (default), a number or a named index");
  cmd->add_option("--film-cauchy-a", o->cauchyA, "Film index by Cauchy's law n = a + b / lambda^2: a");
  cmd->add_option("--film-cauchy-b", o->cauchyB, "Cauchy's b, nm^2 (default 0)");
  cmd->add_option("--ext-ior", given->extIOR, "Index of the surrounding medium (default: air, 1.000277)");
  cmd->add_option("--melanin", o->melaninFile, "Melanin reflectance file: lines of 'wavelength_nm reflectance'");
  cmd->add_option("--layers", o->layers,
                  "Layers under the cortex, from it down: 'INDEX:THICKNESS_UM, ...' (INDEX a number, a named index, "
                  "keratin, melanin or N+Ki), rows of rods 'rods(INDEX, DIAMETER_UM, SPACING_UM[, MATRIX])', "
                  "repeats '[...] x N', or a published stack: parotia-occipital");
  cmd->add_option("--arm-tilts", o->armTilts,
                  "Barbules whose cross-section is a chain of flat arms (barbulearms) with these tilts, degrees, "
                  "e.g. '-30,0,30'; --b and --profile-exponent then shape each arm, --mu and --H the whole");
  cmd->add_option("--angles", o->angles, "Light polar angles from the vane normal, degrees (default 0,20,40,60)")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 89.9));
  cmd->add_option("--phi", o->phiDegrees, "Light azimuth, degrees; 0 = across the barbules (default 0)");
  cmd->add_option("--mode", o->modes,
                  "What to measure, one or more of hemisphere, specular, plane, spectra (the lobes' albedo, to 0.1 %) "
                  "(default hemisphere,spectra)")
      ->delimiter(',')
      ->check(CLI::IsMember({"hemisphere", "specular", "plane", "spectra"}));
  cmd->add_flag("--spectral", o->spectral, "Hemisphere images also as wavelength bins (EXR channels S0.<nm>nm)");
  cmd->add_option("--spectral-range", o->spectralRange,
                  "LO:HI nm, the range of --spectral's bins within 300-830 (default 300:830)")
      ->needs("--spectral");
  cmd->add_option("--bins", o->bins, "Wavelength bins for --spectral (default 16)")->check(CLI::Range(1, 300));
  cmd->add_option("--res", o->resolution, "Hemisphere image size in pixels (default 256)")->check(CLI::Range(16, 4096));
  cmd->add_option("-o,--output", o->outputDir, "Output directory, made if missing (default: the working directory)");
  cmd->add_option("--observer", o->observer,
                  "A bird's visual system (" + builtinObserverNames() +
                      ", or a table of sensitivities or of cone parameters, FILE.csv" +
                      "): with --mode specular, each spectrum's cone catches and colour distances "
                      "(bsdf_specular_catches.csv)")
      ->check([](const std::string& name) {
        return isBuiltinObserver(name) || namesObserverTable(name)
                   ? std::string()
                   : "unknown observer '" + name + "' (known: " + builtinObserverNames() + "; or a table, FILE.csv)";
      });
  cmd->callback([o, given, cmd] {
    if (!o->observer.empty() && std::find(o->modes.begin(), o->modes.end(), "specular") == o->modes.end())
      throw CLI::ValidationError("--observer", "measures the specular spectra's cone catches: add --mode specular");
    bsdfSpectralRange(*o);  // checked before anything is measured
    if (cmd->count("--arm-tilts") > 0 && o->armTilts.find_first_not_of(" \t") == std::string::npos)
      throw CLI::ValidationError("--arm-tilts", "gives no arm: give the arms' tilts in degrees, e.g. '-30,0,30'");
    resolveParameters(*o, *cmd, *given);
    runBSDF(*o);
  });
}

}  // namespace columba
