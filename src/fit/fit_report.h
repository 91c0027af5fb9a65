#pragma once
// The files a fit leaves: fit.json (values, uncertainties, loss, scale, budget used), history.csv
// (every evaluation), profiles.png (the loss slices behind the uncertainties), and compare.png
// (target | fitted render | signed difference) or spectra.png.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>
#include "fit/fit_result.h"
#include "fit/scaled_loss.h"
#include "fit/spectra_fit.h"
#include "io/data_files.h"
#include "io/image.h"
#include "plot/line_plot.h"

namespace columba {

// `settings` describes the run (loss, scale, input files...), copied into the record.
nlohmann::json fitRecord(const FitResult& result, const nlohmann::json& settings);
CsvTable historyTable(const FitResult& result);
// One loss-against-value chart per parameter, over its whole bounds, the threshold and interval
// marked.
std::vector<LinePlot> profilePlots(const FitResult& result);
// Those charts side by side, two to a row.
Image profilesImage(const FitResult& result);
// Target, the render times `scale`, and their signed difference (mean of RGB) in a blue-white-red
// map with its colour bar; pixels outside the mask are grey in the difference.
Image compareImage(const Image& target, const Image& render, double scale, const std::optional<Image>& mask);
// Measured (markers) and fitted (lines) reflectance against wavelength, one colour per pair of
// directions.
LinePlot spectraPlot(const std::vector<SpectraSample>& samples, const std::vector<float>& model, double scale);

}  // namespace columba
