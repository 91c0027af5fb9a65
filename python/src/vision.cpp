// Avian visual models over numpy arrays (src/vision/, docs/vision.md): observers, their cone
// quantum catches of spectra, and receptor-noise-limited colour distances between spectra.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/illuminant.h"
#include "core/spectrum.h"
#include "vision/colour_distance.h"
#include "vision/human_colour_difference.h"
#include "vision/observer.h"
#include "vision/observer_table.h"
#include "vision/quantum_catch.h"

namespace py = pybind11;

namespace columba::python {

namespace {

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// An observer by name or table file (FILE.csv), or one built from published data given as a dict: {"name": ...,
// "lambda_max": [nm, ...], "oil_droplets": [("C", cut_nm) or None, ...], "beta_band": bool,
// "densities": [...], "weber": w, "weber_cone": index}.
Observer observerFrom(const py::object& spec) {
  if (py::isinstance<py::str>(spec)) {
    try {
      return observerNamedOrTabulated(spec.cast<std::string>());
    } catch (const std::invalid_argument& e) {
      throw py::value_error(e.what());
    }
  }
  if (!py::isinstance<py::dict>(spec))
    throw py::type_error(
        "an observer is a name (columba.observers()), a table of sensitivities or of cone parameters (FILE.csv) or a "
        "dict of its cones' "
        "data");
  py::dict d = spec.cast<py::dict>();
  ObserverDefinition definition;
  definition.name = d.contains("name") ? d["name"].cast<std::string>() : "custom";
  if (!d.contains("lambda_max")) throw py::value_error("a custom observer needs 'lambda_max', one per cone (nm)");
  const std::vector<double> peaks = d["lambda_max"].cast<std::vector<double>>();
  const bool beta = d.contains("beta_band") ? d["beta_band"].cast<bool>() : true;
  py::list droplets = d.contains("oil_droplets") ? d["oil_droplets"].cast<py::list>() : py::list();
  if (!droplets.empty() && droplets.size() != peaks.size())
    throw py::value_error("give one oil droplet (or None) per cone in 'oil_droplets'");
  static const char* kNames[][4] = {{"SWS", "LWS", "", ""}, {"SWS", "MWS", "LWS", ""}, {"VS", "SWS", "MWS", "LWS"}};
  if (peaks.size() < 2 || peaks.size() > 4) throw py::value_error("a custom observer has 2 to 4 cones");
  for (size_t i = 0; i < peaks.size(); ++i) {
    if (!(peaks[i] >= 300.0 && peaks[i] <= 700.0))
      throw py::value_error("lambda_max must lie in [300, 700] nm, not " + std::to_string(peaks[i]));
    ConeClass cone{kNames[peaks.size() - 2][i], peaks[i], std::nullopt, beta};
    if (!droplets.empty() && !droplets[i].is_none()) {
      auto [letter, cut] = droplets[i].cast<std::pair<std::string, double>>();
      std::optional<OilDropletType> type = parseOilDropletType(letter);
      if (!type) throw py::value_error("oil droplet type '" + letter + "' is not one of T, C, Y, R, P");
      cone.droplet = oilDropletOfType(*type, cut);
    }
    definition.cones.push_back(cone);
  }
  definition.noise.relativeDensities =
      d.contains("densities") ? d["densities"].cast<std::vector<double>>() : std::vector<double>(peaks.size(), 1.0);
  if (definition.noise.relativeDensities.size() != peaks.size())
    throw py::value_error("give one relative density per cone in 'densities'");
  if (d.contains("weber")) definition.noise.weberFraction = d["weber"].cast<double>();
  const long long weberCone =
      d.contains("weber_cone") ? d["weber_cone"].cast<long long>() : (long long)peaks.size() - 1;
  if (weberCone < 0)
    throw py::value_error("weber_cone " + std::to_string(weberCone) + " names no cone: give 0 to " +
                          std::to_string(peaks.size() - 1));
  definition.noise.weberReference = size_t(weberCone);
  return makeObserver(definition);  // its receptor noise checked there: a ValueError naming the key and value
}

// The one check of every vision function's spectra (reflectances and illuminants): `wavelengths` a
// 1-D increasing array of at least two positive, finite values (nm); `values` one row per
// wavelength (N, or N x k: k spectra in columns, pavo's layout), each value finite, non-negative and
// at most a float's largest (3.4e38; spectra are kept as floats). A ValueError names the argument,
// the index, its wavelength and the value.
void checkSpectra(const DoubleArray& wavelengths, const DoubleArray& values, const char* what) {
  if (wavelengths.ndim() != 1 || wavelengths.shape(0) < 2)
    throw py::value_error("wavelengths must be a 1-D array of at least two values (nm)");
  const py::ssize_t n = wavelengths.shape(0);
  const double* w = wavelengths.data();
  for (py::ssize_t i = 0; i < n; ++i)
    if (!(w[i] > 0.0 && std::isfinite(w[i])))
      throw py::value_error(
          fmt::format("wavelengths[{}] is {:g}: wavelengths must be positive and finite (nm)", i, w[i]));
  for (py::ssize_t i = 1; i < n; ++i)
    if (!(w[i] > w[i - 1])) throw py::value_error("wavelengths must increase");
  if (!((values.ndim() == 1 && values.shape(0) == n) || (values.ndim() == 2 && values.shape(0) == n)))
    throw py::value_error(std::string(what) + " must have one row per wavelength (N, or N x k for k spectra)");
  const py::ssize_t k = values.ndim() == 1 ? 1 : values.shape(1);
  const double* v = values.data();
  for (py::ssize_t i = 0; i < n; ++i)
    for (py::ssize_t j = 0; j < k; ++j)
      if (const double x = v[i * k + j]; !(x >= 0.0 && x <= double(std::numeric_limits<float>::max())))
        throw py::value_error(
            fmt::format("{}[{}] at {:g} nm is {:g}: {} must be finite, non-negative and at most "
                        "3.4e38",
                        what, values.ndim() == 1 ? fmt::format("{}", i) : fmt::format("{}, {}", i, j), w[i], x, what));
}

// Each spectrum (`values` at `wavelengths`, linearly interpolated onto the observer's grid)
// piecewise linear through its samples (core/spectrum.h), read on the grid where it
// was measured and 0 elsewhere.
std::vector<std::vector<float>> interpolated(const SpectralGrid& grid, const DoubleArray& wavelengths,
                                             const DoubleArray& values) {
  const py::ssize_t n = wavelengths.shape(0);
  const double* w = wavelengths.data();
  const py::ssize_t spectra = values.ndim() == 1 ? 1 : values.shape(1);
  const std::vector<float> lambdas(w, w + n);
  const double* v = values.data();
  std::vector<std::vector<float>> out(size_t(spectra), std::vector<float>(grid.count, 0.0f));
  for (py::ssize_t k = 0; k < spectra; ++k) {
    std::vector<float> measured(static_cast<size_t>(n));
    for (py::ssize_t i = 0; i < n; ++i) measured[size_t(i)] = float(v[i * spectra + k]);
    const SpectralDistribution spectrum = SpectralDistribution::piecewiseLinear(lambdas, measured);
    for (size_t g = 0; g < grid.count; ++g) {
      const double x = grid.wavelength(g);
      if (x >= w[0] && x <= w[n - 1]) out[size_t(k)][g] = spectrum.eval(float(x));
    }
  }
  return out;
}

std::vector<std::vector<float>> onGrid(const Observer& observer, const DoubleArray& wavelengths,
                                       const DoubleArray& values, const char* what) {
  checkSpectra(wavelengths, values, what);
  const py::ssize_t n = wavelengths.shape(0);
  const double* w = wavelengths.data();
  // The range the cones see.
  double lo = observer.grid.lastNm(), hi = observer.grid.firstNm;
  auto widen = [&](const std::vector<float>& s) {
    const float peak = *std::max_element(s.begin(), s.end());
    for (size_t i = 0; i < s.size(); ++i)
      if (s[i] > 1e-4f * peak)
        lo = std::min(lo, observer.grid.wavelength(i)), hi = std::max(hi, observer.grid.wavelength(i));
  };
  for (const auto& s : observer.sensitivities) widen(s);
  if (observer.hasAchromatic()) widen(observer.achromatic);
  if (w[0] > lo + 1e-9 || w[n - 1] < hi - 1e-9)
    throw py::value_error(std::string(what) + " must cover " + std::to_string(int(std::floor(lo))) + "-" +
                          std::to_string(int(std::ceil(hi))) + " nm, where observer '" + observer.name +
                          "' is sensitive; it covers " + std::to_string(w[0]) + "-" + std::to_string(w[n - 1]) + " nm");
  return interpolated(observer.grid, wavelengths, values);  // no cone is sensitive outside
}

std::vector<float> illuminantFrom(const Observer& observer, const DoubleArray& wavelengths, const py::object& given) {
  if (given.is_none()) return equalQuantumSpectrum(observer.grid);
  return onGrid(observer, wavelengths, given.cast<DoubleArray>(), "illuminant").front();
}

// A reflectance spectrum's CIELAB colour under `illuminant` (None: D65), a white reflector over the
// same wavelengths the reference white. Spectra must cover 400-700 nm; the colour-matching
// functions outside a spectrum's range are left out.
CIELab humanColour(const DoubleArray& wavelengths, const DoubleArray& reflectance, const py::object& illuminant,
                   const char* what) {
  checkSpectra(wavelengths, reflectance, what);
  if (reflectance.ndim() != 1) throw py::value_error(std::string(what) + " must be one spectrum (N)");
  const double* w = wavelengths.data();
  if (w[0] > 400.0 || w[wavelengths.shape(0) - 1] < 700.0)
    throw py::value_error(std::string(what) + " must cover 400-700 nm for the human observer; it covers " +
                          std::to_string(w[0]) + "-" + std::to_string(w[wavelengths.shape(0) - 1]) + " nm");
  const SpectralGrid grid = visionGrid();
  std::vector<float> light;
  if (illuminant.is_none()) {
    light = tabulateOnGrid(grid, [](double l) { return double(d65(float(l))); });
  } else {
    const DoubleArray given = illuminant.cast<DoubleArray>();
    checkSpectra(wavelengths, given, "illuminant");
    light = interpolated(grid, wavelengths, given).front();
  }
  // The reference white reflects 1 over the spectrum's own range, so that 1 there is white.
  DoubleArray ones(wavelengths.shape(0));
  std::fill(ones.mutable_data(), ones.mutable_data() + ones.size(), 1.0);
  const std::vector<float> white = interpolated(grid, wavelengths, ones).front();
  return labFromXYZ(reflectanceXYZ(grid, interpolated(grid, wavelengths, reflectance).front(), light),
                    reflectanceXYZ(grid, white, light));
}

}  // namespace

void bindVision(py::module_& m) {
  m.def(
      "observers",
      [] {
        py::list names;
        for (const auto& [name, description] : builtinObservers())
          names.append(py::dict(py::arg("name") = name, py::arg("description") = description));
        return names;
      },
      "The built-in avian observers: a list of {name, description} (docs/vision.md gives their sources)");
  m.def(
      "observer",
      [](const py::object& spec) {
        Observer o = observerFrom(spec);
        const py::ssize_t n = py::ssize_t(o.grid.count), k = py::ssize_t(o.channels.size());
        py::array_t<double> wl(n), s({k, n});
        for (py::ssize_t i = 0; i < n; ++i) wl.mutable_at(i) = o.grid.wavelength(size_t(i));
        for (py::ssize_t c = 0; c < k; ++c)
          for (py::ssize_t i = 0; i < n; ++i) s.mutable_at(c, i) = o.sensitivities[size_t(c)][size_t(i)];
        py::dict r;
        r["name"] = o.name;
        r["wavelengths"] = wl;
        r["channels"] = o.channels;
        r["sensitivities"] = s;
        r["densities"] = o.noise.relativeDensities;
        r["weber"] = o.noise.weberFraction;
        r["weber_cone"] = o.channels[o.noise.weberReference];
        r["noise"] = receptorNoise(o.noise);
        return r;
      },
      py::arg("observer"),
      "An observer's sensitivities (channels x wavelengths, each of area 1 per nm) and receptor noise. A dict's "
      "densities must lie within [1e-6, 1e6], its weber within [1e-6, 10] and weber_cone name a cone (ValueError)");
  m.def(
      "cone_catches",
      [](const DoubleArray& wavelengths, const DoubleArray& spectra, const py::object& spec,
         const py::object& illuminant, bool vonKriesAdapted, bool relative) {
        const Observer o = observerFrom(spec);
        const std::vector<std::vector<float>> r = onGrid(o, wavelengths, spectra, "spectra");
        const std::vector<float> light = illuminantFrom(o, wavelengths, illuminant);
        const py::ssize_t k = py::ssize_t(o.channels.size());
        py::array_t<double> out({py::ssize_t(r.size()), k});
        for (size_t s = 0; s < r.size(); ++s) {
          ConeCatches q = vonKriesAdapted ? adaptedQuantumCatches(o, r[s], light) : quantumCatches(o, r[s], light);
          std::vector<double> c = relative ? relativeCatches(q.chromatic) : q.chromatic;
          for (py::ssize_t i = 0; i < k; ++i) out.mutable_at(py::ssize_t(s), i) = c[size_t(i)];
        }
        if (spectra.ndim() == 1) return py::array_t<double>(out.reshape({k}));
        return out;
      },
      py::arg("wavelengths"), py::arg("spectra"), py::arg("observer") = "bluetit", py::arg("illuminant") = py::none(),
      py::arg("von_kries") = true, py::arg("relative") = false,
      "Quantum catches of reflectance spectra (N, or N x k in columns) under an illuminant (default: equal "
      "photon flux), adapted to an ideal white (von Kries) by default; one row per spectrum, one column per cone. "
      "Spectra must be finite, non-negative and at most 3.4e38, wavelengths positive (ValueError naming the value)");
  m.def(
      "colour_distance",
      [](const DoubleArray& wavelengths, const DoubleArray& a, const DoubleArray& b, const py::object& spec,
         const py::object& illuminant) {
        const Observer o = observerFrom(spec);
        const std::vector<float> light = illuminantFrom(o, wavelengths, illuminant);
        const ConeCatches qa = adaptedQuantumCatches(o, onGrid(o, wavelengths, a, "a").front(), light);
        const ConeCatches qb = adaptedQuantumCatches(o, onGrid(o, wavelengths, b, "b").front(), light);
        py::dict r;
        r["dS"] = chromaticDistance(o, qa, qb);
        r["dL"] = o.hasAchromatic() ? py::object(py::float_(achromaticDistance(o, qa, qb))) : py::object(py::none());
        return r;
      },
      py::arg("wavelengths"), py::arg("a"), py::arg("b"), py::arg("observer") = "bluetit",
      py::arg("illuminant") = py::none(),
      "The receptor-noise-limited distance between two reflectance spectra in JND (dS, chromatic; dL, achromatic "
      "where the observer has double cones), Vorobyev & Osorio 1998. Spectra must be finite, non-negative and at "
      "most 3.4e38, wavelengths positive (ValueError naming the value)");
  m.def(
      "human_colour_difference",
      [](const DoubleArray& wavelengths, const DoubleArray& a, const DoubleArray& b, const py::object& illuminant) {
        const CIELab la = humanColour(wavelengths, a, illuminant, "a"),
                     lb = humanColour(wavelengths, b, illuminant, "b");
        py::dict r;
        r["lab_a"] = py::make_tuple(la.L, la.a, la.b);
        r["lab_b"] = py::make_tuple(lb.L, lb.a, lb.b);
        r["dE2000"] = deltaE2000(la, lb);
        r["dEab"] = deltaE1976(la, lb);
        r["jnd"] = deltaE1976(la, lb) / kJustNoticeableDeltaE1976;
        return r;
      },
      py::arg("wavelengths"), py::arg("a"), py::arg("b"), py::arg("illuminant") = py::none(),
      "How far apart two reflectance spectra look to a human (CIE 1931 observer): their CIELAB colours under the "
      "illuminant (default D65), CIEDE2000 and CIE 1976 differences, and the latter in JND at 2.3 a JND. Spectra "
      "must be finite, non-negative and at most 3.4e38, wavelengths positive (ValueError naming the value)");
}

}  // namespace columba::python
