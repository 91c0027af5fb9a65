// `columba.fit` and `columba.fit_spectra`: the fits of `columba fit`, called with numpy arrays and
// returning their results as dicts (the same src/fit code, nothing computed twice).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include "fit/scene_fit.h"
#include "fit/spectra_fit.h"

namespace py = pybind11;

namespace columba::python {

py::array_t<float> imageArray(Image&& image);  // module.cpp
Image imageFromArray(const py::array& input);  // module.cpp

namespace {

// What image and spectra fits share: the varied parameters, the loss and the budgets (checked by
// the fit itself, as for `columba fit`).
template <typename Settings>
void setCommon(Settings& s, const std::vector<std::string>& vary, const std::string& scale, const std::string& loss,
               int maxEvaluations, double maxSeconds, double rise) {
  for (const std::string& text : vary) s.parameters.push_back(parseFitParameter(text));
  s.scale = parseScaleMode(scale);
  s.loss = parseLossKind(loss);
  s.fit.optimizer.maxEvaluations = maxEvaluations;
  s.fit.optimizer.maxSeconds = maxSeconds;
  s.fit.profileRise = rise;
}

// The fields of fit.json, as a dict.
py::dict resultDict(const FitResult& r) {
  py::dict values, intervals, solutions;
  for (size_t i = 0; i < r.parameters.size(); ++i) {
    values[py::str(r.parameters[i].name)] = r.values[i];
    intervals[py::str(r.parameters[i].name)] = py::make_tuple(r.profiles[i].lower, r.profiles[i].upper);
    py::list found;
    for (const ProfileSolution& s : r.profiles[i].solutions)
      found.append(py::dict(py::arg("value") = s.value, py::arg("loss") = s.loss,
                            py::arg("interval") = py::make_tuple(s.lower, s.upper)));
    solutions[py::str(r.parameters[i].name)] = found;
  }
  py::dict d;
  d["values"] = values;
  d["intervals"] = intervals;
  d["solutions"] = solutions;
  d["loss"] = r.loss.loss;
  d["scale"] = r.loss.scale;
  d["evaluations"] = r.evaluations;
  d["profile_evaluations"] = r.profileEvaluations;
  d["seconds"] = r.seconds;
  d["total_seconds"] = r.totalSeconds;
  d["rise"] = r.profileRise;
  return d;
}

py::dict fitImage(const std::filesystem::path& scene, const py::array& target, const std::vector<std::string>& vary,
                  const std::optional<py::array>& mask, const std::map<std::string, std::string>& defines, int spp,
                  uint64_t seed, int threads, const std::string& scale, const std::string& loss, int maxEvaluations,
                  double maxSeconds, double rise) {
  SceneFitSettings s;
  s.scenePath = scene.string();
  s.defines = defines;
  s.target = imageFromArray(target);
  if (mask) s.mask = imageFromArray(*mask);
  setCommon(s, vary, scale, loss, maxEvaluations, maxSeconds, rise);
  s.samplesPerPixel = spp;
  s.seed = seed;
  s.threads = threads;
  SceneFitResult result;
  {
    py::gil_scoped_release release;
    result = fitScene(s);
  }
  py::dict d = resultDict(result.fit);
  d["render"] = imageArray(std::move(result.render));
  return d;
}

// The fitted model beside the spectra it was fitted to, one entry a sample in the file's order:
// its directions and wavelength, the model's reflectance factor before scaling and the measured one.
py::dict modelDict(const std::vector<SpectraSample>& samples, const std::vector<float>& model) {
  const py::ssize_t n = py::ssize_t(samples.size());
  auto column = [&](float SpectraSample::*field) {
    py::array_t<float> a(n);
    for (py::ssize_t i = 0; i < n; ++i) a.mutable_data()[i] = samples[size_t(i)].*field;
    return a;
  };
  py::dict d;
  d["theta_i"] = column(&SpectraSample::thetaI);
  d["phi_i"] = column(&SpectraSample::phiI);
  d["theta_o"] = column(&SpectraSample::thetaO);
  d["phi_o"] = column(&SpectraSample::phiO);
  d["wavelength_nm"] = column(&SpectraSample::wavelength);
  d["reflectance"] = py::array_t<float>(py::ssize_t(model.size()), model.data());
  d["measured"] = column(&SpectraSample::reflectance);
  return d;
}

py::dict fitSpectraFile(const std::filesystem::path& spectra, const std::vector<std::string>& vary,
                        const std::string& scale, const std::string& loss, int maxEvaluations, double maxSeconds,
                        double rise, const std::vector<float>& thetaI, float phiI, const std::string& geometry,
                        float aperture) {
  SpectraGeometry where;
  where.thetaI = thetaI;
  where.phiI = phiI;
  if (geometry != "mirror" && geometry != "normal")
    throw py::value_error("geometry must be 'mirror' or 'normal', not '" + geometry + "'");
  where.view = geometry == "normal" ? SpectraGeometry::View::Normal : SpectraGeometry::View::Mirror;
  SpectraFitSettings s;
  s.samples = readSpectraCSV(spectra.string(), where);
  s.aperture.halfAngleDeg = aperture;
  setCommon(s, vary, scale, loss, maxEvaluations, maxSeconds, rise);
  SpectraFitResult result;
  {
    py::gil_scoped_release release;
    result = fitSpectra(s);
  }
  py::dict d = resultDict(result.fit);
  d["model"] = modelDict(s.samples, result.model);
  py::list warnings;
  if (const std::optional<std::string> w = implausibleScaleWarning(result.fit.loss.scale)) warnings.append(*w);
  d["warnings"] = warnings;
  return d;
}

}  // namespace

void bindFit(py::module_& m) {
  m.def("fit", &fitImage, py::arg("scene"), py::arg("target"), py::arg("vary"), py::arg("mask") = py::none(),
        py::arg("defines") = std::map<std::string, std::string>{}, py::arg("spp") = 0, py::arg("seed") = 0,
        py::arg("threads") = 0, py::arg("scale") = "free", py::arg("loss") = "mse", py::arg("max_evals") = 300,
        py::arg("max_seconds") = 120.0, py::arg("rise") = 0.1,
        "Fit a scene's $variables to a target image (H x W x 3 linear RGB), as `columba fit` does: vary is a list "
        "of 'NAME=LO:HI[:START]'. Returns a dict: values, intervals, loss, scale, evaluations, seconds, render.");
  m.def("fit_spectra", &fitSpectraFile, py::arg("spectra"), py::arg("vary"), py::arg("scale") = "free",
        py::arg("loss") = "mse", py::arg("max_evals") = 300, py::arg("max_seconds") = 120.0, py::arg("rise") = 0.1,
        py::arg("theta_i") = std::vector<float>{}, py::arg("phi_i") = 0.0f, py::arg("geometry") = "mirror",
        py::arg("aperture") = 0.0f,
        "Fit barbule parameters (b, phi_0, phi_1, mu, H, height) to a CSV of measured reflectance spectra, as "
        "`columba fit --spectra` does (theta_i, phi_i, geometry: where spectra without directions were measured; "
        "aperture: the instrument's half-angle in degrees). "
        "Returns a dict: values, intervals, loss, scale, evaluations, model (a dict "
        "of arrays, one entry a sample: theta_i, phi_i, theta_o, phi_o, wavelength_nm, reflectance of the model "
        "before scaling, measured).");
}

}  // namespace columba::python
