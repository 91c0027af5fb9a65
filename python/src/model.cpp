// The barbule BSDF evaluated over numpy arrays, its virtual measurements, the optics it is built
// from (thin film, Fresnel, dispersion, melanin) and the feather generator.
#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <complex>
#include <functional>
#include <string>

#include "barbule/layer_stacks.h"
#include "barbule/measurement.h"
#include "barbule/parameter_reader.h"
#include "bsdfs/barbulearms.h"
#include "bsdfs/barbulebsdf.h"
#include "core/error.h"
#include "feather/feather_generator.h"
#include "io/feather_ply.h"
#include "io/feather_ply_writer.h"
#include "optics/dispersion.h"
#include "optics/film_layer_text.h"
#include "optics/fresnel.h"
#include "optics/layered_film.h"
#include "optics/melanin.h"
#include "optics/multilayer.h"
#include "optics/thin_film.h"

namespace py = pybind11;

namespace columba::python {

py::array_t<float> imageArray(Image&& image);  // module.cpp
PyObject* columbaWarning();                    // module.cpp

namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A float parameter as the shortest decimal that reads back as the same float (0.58, not
// 0.5799999833): Python shows the value as it was written.
double decimal(float x) {
  const std::string text = fmt::format("{}", x);
  double value = x;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

// "<bsdf> 'barbulebsdf', parameter 'b': ..." as the scene plug-in words it (without a file position).
[[noreturn]] void parameterError(const std::string& parameter, const std::string& message) {
  throw py::value_error("<bsdf> 'barbulebsdf', parameter '" + parameter + "': " + message);
}

// A refractive index given as a name ("keratin", "air", ...), a number or (a, b) of Cauchy's law.
RefractiveIndex indexFrom(const py::object& value, const std::string& parameter) {
  if (py::isinstance<py::str>(value)) {
    std::string name = value.cast<std::string>();
    std::optional<RefractiveIndex> ior = iorFromName(name);
    if (!ior) parameterError(parameter, "unknown index of refraction '" + name + "'");
    return *ior;
  }
  RefractiveIndex n;
  if (py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) {
    auto ab = value.cast<std::vector<float>>();
    if (ab.size() != 2) parameterError(parameter, "a Cauchy index is given as (a, b), n = a + b / lambda^2 (nm)");
    n = RefractiveIndex::cauchy(ab[0], ab[1]);
  } else {
    n = RefractiveIndex::constant(value.cast<float>());
  }
  // As a scene's film index is bounded (findProblem): beyond kMaxFilmIndex no material, and the
  // films' arithmetic is not held to stay finite.
  if (!(n.minimumVisible() > 0.0f && n.maximumVisible() <= kMaxFilmIndex))
    parameterError(parameter, fmt::format("the index must lie in (0, {:g}] from 300 to 830 nm, not {:g} to {:g}",
                                          kMaxFilmIndex, n.minimumVisible(), n.maximumVisible()));
  return n;
}

// An index given as a name or number (`name`), or for the film as (a, b) of Cauchy's law
// (film_cauchy_a, film_cauchy_b).
void setIndex(Properties& props, const std::string& name, const py::object& value) {
  if (value.is_none()) return;
  if (py::isinstance<py::str>(value)) {
    props.setString(name, value.cast<std::string>());
  } else if (py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) {
    auto ab = value.cast<std::vector<float>>();
    if (ab.size() != 2) throw props.error(name, "a Cauchy index is given as (a, b), n = a + b / lambda^2 (nm)");
    if (name != "film_ior") throw props.error(name, "the surrounding medium needs a constant index");
    props.setFloat("film_cauchy_a", ab[0]);
    props.setFloat("film_cauchy_b", ab[1]);
  } else {
    props.setFloat(name, value.cast<float>());
  }
}

// A keyword argument given as a number, as the parameter `name` (none: the plug-in's default).
void setFloatIfGiven(Properties& props, const char* name, const py::object& value) {
  if (!value.is_none()) props.setFloat(name, value.cast<float>());
}

class PyBarbule {
 public:
  PyBarbule(const py::object& b, const py::object& H, const py::object& mu, const py::object& height,
            const py::object& phi0, const py::object& phi1, const py::object& filmIOR, const py::object& extIOR,
            const py::object& preset, const py::object& melanin, const py::object& layers,
            const py::object& profileExponent, const py::object& trtOffsets, const py::object& trtAngles,
            const std::string& role)
      : PyBarbule(resolve(b, H, mu, height, phi0, phi1, filmIOR, extIOR, preset, melanin, layers, profileExponent,
                          trtOffsets, trtAngles),
                  roleFrom(role)) {}

  const BarbuleBSDF& bsdf() const { return bsdf_; }

 private:
  static BarbuleBSDF::Role roleFrom(const std::string& role) {
    if (role == "camera") return BarbuleBSDF::Role::CameraIncident;
    if (role == "light") return BarbuleBSDF::Role::LightIncident;
    throw py::value_error("role must be 'camera' (barbulebsdf) or 'light' (barbulebsdfev), not '" + role + "'");
  }

  struct Resolved {
    BarbuleParameters params;
    BarbuleQuadrature quadrature;
  };
  PyBarbule(const Resolved& r, BarbuleBSDF::Role role) : bsdf_(r.params, role, r.quadrature) {}

  // The keyword arguments as Properties, read as a scene's <bsdf type="barbulebsdf"> is (errors
  // are columba.InputError, a ValueError, worded as the plug-in's without a file position).
  static Resolved resolve(const py::object& b, const py::object& H, const py::object& mu, const py::object& height,
                          const py::object& phi0, const py::object& phi1, const py::object& filmIOR,
                          const py::object& extIOR, const py::object& preset, const py::object& melanin,
                          const py::object& layers, const py::object& profileExponent, const py::object& trtOffsets,
                          const py::object& trtAngles) {
    Properties props;
    props.tag = "bsdf";
    props.type = "barbulebsdf";
    if (!preset.is_none()) props.setString("preset", preset.cast<std::string>());
    setFloatIfGiven(props, "b", b);
    setFloatIfGiven(props, "H", H);
    setFloatIfGiven(props, "mu", mu);
    setFloatIfGiven(props, "height", height);
    setFloatIfGiven(props, "phi_0", phi0);
    setFloatIfGiven(props, "phi_1", phi1);
    setFloatIfGiven(props, "profile_exponent", profileExponent);
    if (!trtOffsets.is_none()) props.setInt("trt_offsets", trtOffsets.cast<int>());
    if (!trtAngles.is_none()) props.setInt("trt_angles", trtAngles.cast<int>());
    setIndex(props, "film_ior", filmIOR);
    setIndex(props, "ext_ior", extIOR);
    if (!melanin.is_none()) {
      if (py::isinstance<py::float_>(melanin) || py::isinstance<py::int_>(melanin)) {
        props.setFloat("melanin", melanin.cast<float>());
      } else {
        auto pair = melanin.cast<std::pair<std::vector<float>, std::vector<float>>>();
        if (pair.first.size() != pair.second.size() || pair.first.empty())
          throw props.error("melanin", "give (wavelengths, reflectances) of the same, non-zero length");
        if (!std::is_sorted(pair.first.begin(), pair.first.end()))
          throw props.error("melanin", "the wavelengths must increase");
        const float lowest = *std::min_element(pair.second.begin(), pair.second.end());
        props.setSpectrum("melanin", SpectralDistribution::piecewiseLinear(pair.first, pair.second), lowest);
      }
    }
    if (!layers.is_none()) props.setString("layers", layers.cast<std::string>());
    std::optional<BarbuleParameterProblem> odd;
    BarbuleParameters p = readBarbuleParameters(props, odd);
    if (odd) {
      std::string text = "<bsdf> 'barbulebsdf', parameter '" + odd->parameter + "': " + odd->message;
      if (PyErr_WarnEx(columbaWarning(), text.c_str(), 1) != 0) throw py::error_already_set();
    }
    return {p, readBarbuleQuadrature(props)};
  }

  BarbuleBSDF bsdf_;
};

// barbulearms, from keyword arguments read as a scene's <bsdf type="barbulearms"> is.
class PyArms {
 public:
  PyArms(const py::object& armTilts, const py::object& b, const py::object& profileExponent, const py::object& mu,
         const py::object& H, const py::object& height, const py::object& filmIOR, const py::object& extIOR,
         const py::object& layers) {
    Properties props;
    props.tag = "bsdf";
    props.type = "barbulearms";
    if (py::isinstance<py::str>(armTilts)) {
      props.setString("arm_tilts", armTilts.cast<std::string>());
    } else {
      std::string text;
      for (double tilt : armTilts.cast<std::vector<double>>())
        text += (text.empty() ? "" : ", ") + fmt::format("{}", tilt);
      props.setString("arm_tilts", text);
    }
    setFloatIfGiven(props, "b", b);
    setFloatIfGiven(props, "profile_exponent", profileExponent);
    setFloatIfGiven(props, "mu", mu);
    setFloatIfGiven(props, "H", H);
    setFloatIfGiven(props, "height", height);
    setIndex(props, "film_ior", filmIOR);
    setIndex(props, "ext_ior", extIOR);
    if (!layers.is_none()) props.setString("layers", layers.cast<std::string>());
    bsdf_ = std::static_pointer_cast<BarbuleArmsBSDF>(makeBarbuleArmsBSDF(props));
  }
  const BarbuleArmsBSDF& bsdf() const { return *bsdf_; }

 private:
  std::shared_ptr<BarbuleArmsBSDF> bsdf_;
};

// N x 3 directions.
// Directions as unit vectors: a row whose length differs from 1 by more than 1e-5 is normalised
// (the BSDF's formulas take unit vectors; a direction scaled by 3 read 0.0346 where 0.0976 is its
// value), one within it taken as given, so that a float32 unit vector (a sample's wo) is the same
// direction bit for bit; a zero or non-finite row is refused, naming it.
FloatArray directions(const py::array& input, const char* name) {
  DoubleArray a = DoubleArray::ensure(input);
  if (!a || a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error(std::string(name) + " must be an N x 3 array of directions in the local frame");
  FloatArray unit({a.shape(0), py::ssize_t(3)});
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    const double* v = a.data() + 3 * i;
    const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(length > 0.0) || !std::isfinite(length))
      throw py::value_error(
          fmt::format("{} row {} ({:g}, {:g}, {:g}) is not a direction: give a finite, non-zero "
                      "vector (it is normalised)",
                      name, i, v[0], v[1], v[2]));
    const double scale = std::abs(length - 1.0) > 1e-5 ? 1.0 / length : 1.0;
    for (int c = 0; c < 3; ++c) unit.mutable_data()[3 * i + c] = float(v[c] * scale);
  }
  return unit;
}

// Uniform random numbers for sampling, in [0, 1] as float64 gives them: numpy's random() draws
// 1 - 2^-53, which rounds to 1 in float32, so numbers are checked in double and then held below 1
// (the largest float32 under 1), as the samplers' own are. NaN and numbers outside [0, 1] are
// refused, naming the element.
FloatArray uniformNumbers(const py::array& input, const char* name) {
  DoubleArray a = DoubleArray::ensure(input);
  if (!a) throw py::value_error(std::string(name) + " must be a numeric array");
  FloatArray u(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()));
  for (py::ssize_t i = 0; i < a.size(); ++i) {
    const double v = a.data()[i];
    if (!(v >= 0.0 && v <= 1.0))
      throw py::value_error(fmt::format("{} must lie in [0, 1], not {:g} (element {})", name, v, i));
    u.mutable_data()[i] = std::min(float(v), kOneMinusEpsilon);
  }
  return u;
}

// The wavelengths the BSDF is evaluated at: the renderer's range, birds' ultraviolet included (NaN
// is in no range).
void requireVisible(const float* lambdas, py::ssize_t count) {
  for (py::ssize_t i = 0; i < count; ++i)
    if (!(lambdas[i] >= kSpectralMin && lambdas[i] <= kLambdaMax))
      throw py::value_error(fmt::format("wavelengths (nm) must lie in [{:g}, {:g}], not {:g} (element {})",
                                        kSpectralMin, kLambdaMax, lambdas[i], i));
}

// Wavelengths (nm), N (one per direction, in all four lanes) or N x 4 (a path's four).
struct WavelengthArg {
  FloatArray a;
  bool four = false;
  Wavelengths at(py::ssize_t i) const {
    const float* p = a.data();
    if (four) return Wavelengths::fixed({p[4 * i], p[4 * i + 1], p[4 * i + 2], p[4 * i + 3]});
    return Wavelengths::fixed({p[i], p[i], p[i], p[i]});
  }
};
WavelengthArg wavelengths(const py::array& input, py::ssize_t n) {
  WavelengthArg w{FloatArray::ensure(input)};
  if (!w.a) throw py::value_error("wavelengths must be a numeric array");
  bool single = w.a.ndim() == 1 && w.a.shape(0) == n;
  w.four = w.a.ndim() == 2 && w.a.shape(0) == n && w.a.shape(1) == 4;
  if (!single && !w.four)
    throw py::value_error("wavelengths must have shape (N,) or (N, 4) for N = " + std::to_string(n) +
                          " directions, not " + py::str(py::tuple(input.attr("shape"))).cast<std::string>());
  requireVisible(w.a.data(), w.a.size());
  return w;
}

// An output spectrum array shaped like the wavelengths.
py::array_t<float> spectrumArray(const WavelengthArg& w, py::ssize_t n) {
  if (w.four) return py::array_t<float>({n, py::ssize_t(4)});
  return py::array_t<float>(n);
}
void store(float* out, const WavelengthArg& w, py::ssize_t i, const Spectrum& s) {
  if (w.four)
    for (int k = 0; k < 4; ++k) out[4 * i + k] = s[k];
  else
    out[i] = s[0];
}

Vec3 row(const FloatArray& a, py::ssize_t i) {
  const float* p = a.data() + 3 * i;
  return Vec3(p[0], p[1], p[2]);
}

void sameCount(const FloatArray& a, const FloatArray& b, const char* na, const char* nb) {
  if (a.shape(0) != b.shape(0))
    throw py::value_error(std::string(na) + " and " + nb + " must have the same number of rows (" +
                          std::to_string(a.shape(0)) + " and " + std::to_string(b.shape(0)) + ")");
}

// Any wrapper whose bsdf() is the BSDF: barbulebsdf's and barbulearms'.
template <typename Wrapper>
py::array_t<float> evalArray(const Wrapper& self, const py::array& wiIn, const py::array& woIn, const py::array& wlIn) {
  FloatArray wi = directions(wiIn, "wi"), wo = directions(woIn, "wo");
  sameCount(wi, wo, "wi", "wo");
  py::ssize_t n = wi.shape(0);
  WavelengthArg wl = wavelengths(wlIn, n);
  py::array_t<float> out = spectrumArray(wl, n);
  float* o = out.mutable_data();
  py::gil_scoped_release release;
  BSDFContext ctx;
  for (py::ssize_t i = 0; i < n; ++i) store(o, wl, i, self.bsdf().eval(ctx, row(wi, i), row(wo, i), wl.at(i)));
  return out;
}

template <typename Wrapper>
py::array_t<float> pdfArray(const Wrapper& self, const py::array& wiIn, const py::array& woIn, const py::array& wlIn) {
  FloatArray wi = directions(wiIn, "wi"), wo = directions(woIn, "wo");
  sameCount(wi, wo, "wi", "wo");
  py::ssize_t n = wi.shape(0);
  WavelengthArg wl = wavelengths(wlIn, n);
  py::array_t<float> out(n);
  float* o = out.mutable_data();
  py::gil_scoped_release release;
  BSDFContext ctx;
  for (py::ssize_t i = 0; i < n; ++i) o[i] = self.bsdf().pdf(ctx, row(wi, i), row(wo, i), wl.at(i));
  return out;
}

template <typename Wrapper>
py::dict sampleArray(const Wrapper& self, const py::array& wiIn, const py::array& u1In, const py::array& u2In,
                     const py::array& wlIn) {
  FloatArray wi = directions(wiIn, "wi");
  py::ssize_t n = wi.shape(0);
  FloatArray u1 = uniformNumbers(u1In, "u1"), u2 = uniformNumbers(u2In, "u2");
  if (u1.ndim() != 1 || u1.shape(0) != n) throw py::value_error("u1 must have shape (N,): one number per direction");
  if (u2.ndim() != 2 || u2.shape(0) != n || u2.shape(1) != 2)
    throw py::value_error("u2 must have shape (N, 2): two numbers per direction");
  WavelengthArg wl = wavelengths(wlIn, n);
  py::array_t<float> wo({n, py::ssize_t(3)}), pdf(n);
  py::array_t<float> weight = spectrumArray(wl, n);
  py::array_t<bool> valid(n), delta(n), passThrough(n);
  {
    float *pWo = wo.mutable_data(), *pPdf = pdf.mutable_data(), *pWeight = weight.mutable_data();
    bool *pValid = valid.mutable_data(), *pDelta = delta.mutable_data(), *pPass = passThrough.mutable_data();
    py::gil_scoped_release release;
    BSDFContext ctx;
    for (py::ssize_t i = 0; i < n; ++i) {
      std::optional<BSDFSample> s =
          self.bsdf().sample(ctx, row(wi, i), wl.at(i), u1.data()[i], Vec2(u2.data()[2 * i], u2.data()[2 * i + 1]));
      BSDFSample v = s.value_or(BSDFSample{});
      pWo[3 * i] = v.wo.x;
      pWo[3 * i + 1] = v.wo.y;
      pWo[3 * i + 2] = v.wo.z;
      pPdf[i] = v.pdf;
      store(pWeight, wl, i, v.weight);
      pValid[i] = s.has_value();
      pDelta[i] = v.delta;
      pPass[i] = v.passThrough;
    }
  }
  py::dict d;
  d["wo"] = wo;
  d["weight"] = weight;
  d["pdf"] = pdf;
  d["valid"] = valid;
  d["delta"] = delta;
  d["pass_through"] = passThrough;
  return d;
}

py::dict lobesArray(const PyBarbule& self, const py::array& wiIn, const py::array& woIn, const py::array& wlIn) {
  FloatArray wi = directions(wiIn, "omega_i"), wo = directions(woIn, "omega_o");
  sameCount(wi, wo, "omega_i", "omega_o");
  py::ssize_t n = wi.shape(0);
  WavelengthArg wl = wavelengths(wlIn, n);
  py::array_t<float> r = spectrumArray(wl, n), trt = spectrumArray(wl, n);
  {
    float *pr = r.mutable_data(), *pt = trt.mutable_data();
    py::gil_scoped_release release;
    BSDFContext ctx;
    for (py::ssize_t i = 0; i < n; ++i) {
      BarbuleBSDF::Lobes l = self.bsdf().evalLobes(ctx, row(wi, i), row(wo, i), wl.at(i));
      store(pr, wl, i, l.reflection);
      store(pt, wl, i, l.trt);
    }
  }
  py::dict d;
  d["R"] = r;
  d["TRT"] = trt;
  return d;
}

py::array_t<float> coverageArray(const PyBarbule& self, const py::array& wiIn) {
  FloatArray wi = directions(wiIn, "omega_i");
  py::ssize_t n = wi.shape(0);
  py::array_t<float> out(n);
  float* o = out.mutable_data();
  py::gil_scoped_release release;
  BSDFContext ctx;
  for (py::ssize_t i = 0; i < n; ++i) o[i] = self.bsdf().coverage(ctx, row(wi, i));
  return out;
}

template <typename Wrapper>
py::array_t<float> passThroughArray(const Wrapper& self, const py::array& wiIn, const py::array& wlIn) {
  FloatArray wi = directions(wiIn, "wi");
  py::ssize_t n = wi.shape(0);
  WavelengthArg wl = wavelengths(wlIn, n);
  py::array_t<float> out = spectrumArray(wl, n);
  float* o = out.mutable_data();
  py::gil_scoped_release release;
  BSDFContext ctx;
  for (py::ssize_t i = 0; i < n; ++i) store(o, wl, i, self.bsdf().passThrough(ctx, row(wi, i), wl.at(i)));
  return out;
}

std::vector<float> lambdaList(const py::object& lambdas) {
  if (lambdas.is_none()) return wavelengthGrid(kSpectralMin, 1.0f);
  FloatArray a = FloatArray::ensure(lambdas);
  if (!a || a.ndim() != 1 || a.size() == 0) throw py::value_error("wavelengths must be a non-empty 1-D array (nm)");
  requireVisible(a.data(), a.size());
  return std::vector<float>(a.data(), a.data() + a.size());
}

py::array_t<float> toArray(const std::vector<float>& v) { return py::array_t<float>(py::ssize_t(v.size()), v.data()); }

// What an imaging scatterometer records (barbule/measurement.h), as an H x W x 3 array.
py::array_t<float> scatterometerArray(const BarbuleLobeSource& source, float theta, float phi, int resolution,
                                      int supersampling) {
  if (resolution < 1 || resolution > 8192) throw py::value_error("resolution must be between 1 and 8192");
  if (supersampling < 1 || supersampling > 64) throw py::value_error("supersampling must be between 1 and 64");
  Image image;
  {
    py::gil_scoped_release release;
    image = scatterometerImage(source, directionFromAngles(degToRad(theta), degToRad(phi)), resolution, supersampling);
  }
  return imageArray(std::move(image));
}

// The lobes' spectra for light at (theta, phi) degrees, measured by `measure` (lobeReflectance or
// specularSpectra) without the GIL, as {wavelengths, R, TRT}.
template <typename Measure>
py::dict lobeSpectraDict(const BarbuleLobeSource& source, float theta, float phi, const py::object& lambdas,
                         Measure measure) {
  std::vector<float> l = lambdaList(lambdas);
  LobeSpectra r;
  {
    py::gil_scoped_release release;
    r = measure(source, directionFromAngles(degToRad(theta), degToRad(phi)), l);
  }
  py::dict d;
  d["wavelengths"] = toArray(r.lambdas), d["R"] = toArray(r.reflection), d["TRT"] = toArray(r.trt);
  return d;
}

// Broadcast 1-D inputs of equal length (the Python side broadcasts and flattens).
void equalLengths(std::initializer_list<const DoubleArray*> arrays) {
  py::ssize_t n = (*arrays.begin())->size();
  for (const DoubleArray* a : arrays)
    if (a->size() != n) throw py::value_error("the arrays must have the same length");
}

py::dict thinFilm(const DoubleArray& theta, const DoubleArray& lambda, const DoubleArray& thickness,
                  const py::object& filmIOR, double nOutside, const py::object& substrateIOR) {
  equalLengths({&theta, &lambda, &thickness});
  RefractiveIndex film = indexFrom(filmIOR, "film_ior");
  std::optional<RefractiveIndex> substrate;
  if (!substrateIOR.is_none()) substrate = indexFrom(substrateIOR, "substrate_ior");
  py::ssize_t n = theta.size();
  const char* names[] = {"Rs", "Rp", "R", "Ts", "Tp", "T"};
  std::vector<py::array_t<double>> out;
  for (int k = 0; k < 6; ++k) out.emplace_back(n);
  std::vector<double*> p;
  for (auto& a : out) p.push_back(a.mutable_data());
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < n; ++i) {
      double l = lambda.data()[i];
      double n2 = film(float(l)), n3 = substrate ? (*substrate)(float(l)) : nOutside;
      double c = std::cos(theta.data()[i] * (M_PI / 180.0));
      ThinFilmAmplitudes a = thinFilmAmplitudes(c, nOutside, n2, n3, thickness.data()[i], l);
      double rs = std::norm(a.rs), rp = std::norm(a.rp);
      double ts = a.transmittanceFactor * std::norm(a.ts), tp = a.transmittanceFactor * std::norm(a.tp);
      p[0][i] = rs;
      p[1][i] = rp;
      p[2][i] = thinFilmReflectance(c, nOutside, n2, n3, thickness.data()[i], l);
      p[3][i] = ts;
      p[4][i] = tp;
      p[5][i] = thinFilmTransmittance(c, nOutside, n2, n3, thickness.data()[i], l);
    }
  }
  py::dict d;
  for (int k = 0; k < 6; ++k) d[names[k]] = out[size_t(k)];
  return d;
}

// A layer's complex index at a wavelength: a complex number (n + ik) taken as it is, otherwise an
// index as indexFrom reads it (a name, a number, Cauchy's (a, b)).
std::function<std::complex<double>(double)> complexIndexFrom(const py::object& value, const std::string& what) {
  if (PyComplex_Check(value.ptr())) {
    const std::complex<double> n = value.cast<std::complex<double>>();
    return [n](double) { return n; };
  }
  if (py::isinstance<py::str>(value) && value.cast<std::string>() == "melanin")
    return [m = melanin()](double lambda) { return m.index(float(lambda)); };
  const RefractiveIndex n = indexFrom(value, what);
  return [n](double lambda) { return std::complex<double>(n(float(lambda)), 0.0); };
}

// Intensity reflectance and transmittance of a stack of layers (optics/multilayer.h) at each
// (angle, wavelength) pair: `layers` a list of (index, thickness_um), or the text a scene's
// `layers` takes (optics/film_layer_text.h, or a named stack), whose repeats are kept.
py::dict multilayer(const DoubleArray& theta, const DoubleArray& lambda, const py::object& layers,
                    const py::object& outside, const py::object& substrate) {
  equalLengths({&theta, &lambda});
  std::vector<std::function<std::complex<double>(double)>> indices;
  std::vector<double> thicknesses;
  std::vector<LayerRun> runs;
  if (py::isinstance<py::str>(layers)) {
    FilmStack text;
    try {
      text = parseFilmLayers(expandLayerStack(layers.cast<std::string>()));
    } catch (const std::invalid_argument& e) {
      throw py::value_error(e.what());
    }
    for (const FilmLayer& layer : text.layers) {
      indices.push_back([layer](double l) { return layer.index(float(l)); });
      thicknesses.push_back(layer.thicknessUm);
    }
    runs = text.runs;
  } else {
    for (const py::handle& item : layers.cast<py::list>()) {
      const py::tuple layer = py::reinterpret_borrow<py::object>(item).cast<py::tuple>();
      if (layer.size() != 2) throw py::value_error("a layer is (index, thickness_um)");
      indices.push_back(complexIndexFrom(layer[0], "layer index"));
      thicknesses.push_back(layer[1].cast<double>());
    }
  }
  const RefractiveIndex outer = indexFrom(outside, "n_outside");
  const auto inner = complexIndexFrom(substrate, "substrate_ior");
  const py::ssize_t n = theta.size();
  const char* names[] = {"Rs", "Rp", "R", "Ts", "Tp", "T", "A"};
  std::vector<py::array_t<double>> out;
  for (int k = 0; k < 7; ++k) out.emplace_back(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    const double l = lambda.data()[i];
    LayerStack stack{outer(float(l)), {}, inner(l), runs};
    for (size_t j = 0; j < indices.size(); ++j) stack.layers.push_back({indices[j](l), thicknesses[j]});
    MultilayerResponse r;
    try {
      r = multilayerResponse(stack, theta.data()[i] * (M_PI / 180.0), l);
    } catch (const std::invalid_argument& e) {
      throw py::value_error(
          fmt::format("theta_deg {:g}, wavelength {:g} (element {}): {}", theta.data()[i], l, i, e.what()));
    }
    const double values[] = {r.rs, r.rp, r.reflectance(), r.ts, r.tp, r.transmittance(), r.absorptance()};
    for (int k = 0; k < 7; ++k) out[size_t(k)].mutable_data()[i] = values[k];
  }
  py::dict d;
  for (int k = 0; k < 7; ++k) d[names[k]] = out[size_t(k)];
  return d;
}

py::dict featherPly(const std::string& path) {
  FeatherPlyData data;
  {
    py::gil_scoped_release release;
    data = readFeatherPly(path);
  }
  py::ssize_t barbs = py::ssize_t(data.barbCount());
  py::array_t<float> positions({barbs, py::ssize_t(kBarbVertices), py::ssize_t(3)});
  py::array_t<float> normals({barbs, py::ssize_t(kBarbVertices), py::ssize_t(3)});
  float *pp = positions.mutable_data(), *pn = normals.mutable_data();
  for (size_t i = 0; i < data.barbIndices.size(); ++i) {
    uint32_t v = data.barbIndices[i];
    const Vec3 &x = data.positions[v], &nrm = data.normals[v];
    pp[3 * i] = x.x, pp[3 * i + 1] = x.y, pp[3 * i + 2] = x.z;
    pn[3 * i] = nrm.x, pn[3 * i + 1] = nrm.y, pn[3 * i + 2] = nrm.z;
  }
  py::dict d;
  d["positions"] = positions;
  d["normals"] = normals;
  if (data.hasBarbuleValues()) {
    py::array_t<float> H({barbs, py::ssize_t(kBarbVertices)}), mu({barbs, py::ssize_t(kBarbVertices)}),
        height({barbs, py::ssize_t(kBarbVertices)});
    for (size_t i = 0; i < data.barbIndices.size(); ++i) {
      uint32_t v = data.barbIndices[i];
      H.mutable_data()[i] = data.barbuleH[v];
      mu.mutable_data()[i] = data.barbuleMu[v];
      height.mutable_data()[i] = data.barbuleHeight[v];
    }
    d["H"] = H;
    d["mu"] = mu;
    d["height"] = height;
  } else {
    d["H"] = py::none();
    d["mu"] = py::none();
    d["height"] = py::none();
  }
  if (!data.layerStack.empty()) {
    py::array_t<uint8_t> stack({barbs, py::ssize_t(kBarbVertices)});
    for (size_t i = 0; i < data.barbIndices.size(); ++i) stack.mutable_data()[i] = data.layerStack[data.barbIndices[i]];
    d["stack"] = stack;
  } else {
    d["stack"] = py::none();
  }
  d["barb_width"] = data.barbWidth ? py::object(py::float_(*data.barbWidth)) : py::object(py::none());
  return d;
}

// Writes arrays as read_feather_ply returns them (the Python wrapper has checked their shapes).
void writeFeatherPlyArrays(const std::string& path, const FloatArray& positions, const FloatArray& normals,
                           const py::object& H, const py::object& mu, const py::object& height, const py::object& stack,
                           std::optional<float> barbWidth, bool binary) {
  const size_t barbs = size_t(positions.shape(0));
  const bool values = !H.is_none(), stacks = !stack.is_none();
  FloatArray h = values ? H.cast<FloatArray>() : FloatArray(), m = values ? mu.cast<FloatArray>() : FloatArray(),
             t = values ? height.cast<FloatArray>() : FloatArray();
  py::array_t<uint8_t, py::array::c_style | py::array::forcecast> s =
      stacks ? stack.cast<py::array_t<uint8_t, py::array::c_style | py::array::forcecast>>()
             : py::array_t<uint8_t, py::array::c_style | py::array::forcecast>();
  py::gil_scoped_release release;
  FeatherPlyWriter writer(path, binary, barbs, barbWidth, {values, stacks});
  BarbVertex vertices[kBarbVertices];
  const float *p = positions.data(), *n = normals.data();
  for (size_t b = 0; b < barbs; ++b) {
    for (int k = 0; k < kBarbVertices; ++k) {
      const size_t i = b * kBarbVertices + size_t(k);
      vertices[k].position = Vec3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
      vertices[k].normal = Vec3(n[3 * i], n[3 * i + 1], n[3 * i + 2]);
      if (values) vertices[k].fileH = h.data()[i], vertices[k].fileMu = m.data()[i], vertices[k].height = t.data()[i];
      if (stacks) vertices[k].stack = s.data()[i];
    }
    writer.writeBarb(vertices);
  }
  writer.commit();
}

}  // namespace

void bindModel(py::module_& m) {
  py::class_<PyBarbule>(m, "BarbuleBSDF",
                        "The barbule BSDF (barbulebsdf; role='light' gives barbulebsdfev). Directions are N x 3 "
                        "arrays in the local frame (z the vane normal, y the barbule axis), wavelengths (nm) N or "
                        "N x 4.")
      .def(py::init<const py::object&, const py::object&, const py::object&, const py::object&, const py::object&,
                    const py::object&, const py::object&, const py::object&, const py::object&, const py::object&,
                    const py::object&, const py::object&, const py::object&, const py::object&, const std::string&>(),
           py::kw_only(), py::arg("b") = py::none(), py::arg("H") = py::none(), py::arg("mu") = py::none(),
           py::arg("height") = py::none(), py::arg("phi_0") = py::none(), py::arg("phi_1") = py::none(),
           py::arg("film_ior") = py::none(), py::arg("ext_ior") = py::none(), py::arg("preset") = py::none(),
           py::arg("melanin") = py::none(), py::arg("layers") = py::none(), py::arg("profile_exponent") = py::none(),
           py::arg("trt_offsets") = py::none(), py::arg("trt_angles") = py::none(), py::arg("role") = "camera")
      .def_property_readonly("parameters",
                             [](const PyBarbule& s) {
                               const BarbuleParameters& p = s.bsdf().parameters();
                               py::dict d;
                               d["b"] = decimal(p.b), d["H"] = decimal(p.H), d["mu"] = decimal(p.mu);
                               d["height"] = decimal(p.height), d["phi_0"] = decimal(p.phi0);
                               d["phi_1"] = decimal(p.phi1), d["ext_ior"] = decimal(p.extIOR);
                               d["profile_exponent"] = decimal(p.profileExponent);
                               return d;
                             })
      .def("eval", &evalArray<PyBarbule>, py::arg("wi"), py::arg("wo"), py::arg("wavelengths"),
           "f(wi, wo) |cos wo| per wavelength (the scene plug-in's eval)")
      .def("pdf", &pdfArray<PyBarbule>, py::arg("wi"), py::arg("wo"), py::arg("wavelengths"))
      .def("sample", &sampleArray<PyBarbule>, py::arg("wi"), py::arg("u1"), py::arg("u2"), py::arg("wavelengths"),
           "Samples wo from wi: u1 (N,) picks the lobe, u2 (N, 2) drives it")
      .def("eval_lobes", &lobesArray, py::arg("omega_i"), py::arg("omega_o"), py::arg("wavelengths"),
           "The R and TRT lobes f(omega_i, omega_o) without cosine")
      .def("coverage", &coverageArray, py::arg("omega_i"), "r(omega_i); T = 1 - r")
      .def("pass_through", &passThroughArray<PyBarbule>, py::arg("wi"), py::arg("wavelengths"), "The T lobe's weight")
      .def(
          "scatterometer_image",
          [](const PyBarbule& s, float theta, float phi, int resolution, int supersampling) {
            return scatterometerArray(s.bsdf().model(), theta, phi, resolution, supersampling);
          },
          py::arg("theta_deg"), py::arg("phi_deg") = 0.0f, py::arg("resolution") = 256, py::arg("supersampling") = 2)
      .def(
          "specular_spectra",
          [](const PyBarbule& s, float theta, float phi, const py::object& lambdas) {
            return lobeSpectraDict(s.bsdf().model(), theta, phi, lambdas, specularSpectra);
          },
          py::arg("theta_deg"), py::arg("phi_deg") = 0.0f, py::arg("wavelengths") = py::none())
      .def(
          "lobe_reflectance",
          [](const PyBarbule& s, float theta, float phi, const py::object& lambdas) {
            return lobeSpectraDict(s.bsdf().model(), theta, phi, lambdas, lobeReflectance);
          },
          py::arg("theta_deg"), py::arg("phi_deg") = 0.0f, py::arg("wavelengths") = py::none());

  py::class_<PyArms>(m, "BarbuleArmsBSDF",
                     "Barbules whose cross-section is a chain of flat arms (barbulearms): arm_tilts in degrees "
                     "(a string '-30, 0, 30' or a sequence). Directions as BarbuleBSDF's.")
      .def(py::init<const py::object&, const py::object&, const py::object&, const py::object&, const py::object&,
                    const py::object&, const py::object&, const py::object&, const py::object&>(),
           py::kw_only(), py::arg("arm_tilts"), py::arg("b") = py::none(), py::arg("profile_exponent") = py::none(),
           py::arg("mu") = py::none(), py::arg("H") = py::none(), py::arg("height") = py::none(),
           py::arg("film_ior") = py::none(), py::arg("ext_ior") = py::none(), py::arg("layers") = py::none())
      .def_property_readonly(
          "spacing", [](const PyArms& s) { return s.bsdf().geometry().spacing(); },
          "H as used: the given spacing, or the contact spacing where that is larger")
      .def("eval", &evalArray<PyArms>, py::arg("wi"), py::arg("wo"), py::arg("wavelengths"),
           "f(wi, wo) |cos wo| per wavelength (the scene plug-in's eval)")
      .def("pdf", &pdfArray<PyArms>, py::arg("wi"), py::arg("wo"), py::arg("wavelengths"))
      .def("sample", &sampleArray<PyArms>, py::arg("wi"), py::arg("u1"), py::arg("u2"), py::arg("wavelengths"),
           "Samples wo from wi: u1 (N,) picks the offset across a period, u2 (N, 2) the longitudinal angle")
      .def(
          "coverage",
          [](const PyArms& s, const py::array& wiIn) {
            FloatArray wi = directions(wiIn, "omega_i");
            py::array_t<float> out(wi.shape(0));
            float* o = out.mutable_data();
            py::gil_scoped_release release;
            for (py::ssize_t i = 0; i < wi.shape(0); ++i) o[i] = s.bsdf().coverage(row(wi, i));
            return out;
          },
          py::arg("omega_i"), "The share of light from omega_i meeting a film-coated side; T = 1 - coverage")
      .def("pass_through", &passThroughArray<PyArms>, py::arg("wi"), py::arg("wavelengths"), "The T lobe's weight")
      .def(
          "scatterometer_image",
          [](const PyArms& s, float theta, float phi, int resolution, int supersampling) {
            return scatterometerArray(s.bsdf(), theta, phi, resolution, supersampling);
          },
          py::arg("theta_deg"), py::arg("phi_deg") = 0.0f, py::arg("resolution") = 256, py::arg("supersampling") = 2)
      .def(
          "specular_spectra",
          [](const PyArms& s, float theta, float phi, const py::object& lambdas) {
            return lobeSpectraDict(s.bsdf(), theta, phi, lambdas, specularSpectra);
          },
          py::arg("theta_deg"), py::arg("phi_deg") = 0.0f, py::arg("wavelengths") = py::none(),
          "As BarbuleBSDF's; TRT is 0")
      .def(
          "lobe_reflectance",
          [](const PyArms& s, float theta, float phi, const py::object& lambdas) {
            return lobeSpectraDict(s.bsdf(), theta, phi, lambdas, lobeReflectance);
          },
          py::arg("theta_deg"), py::arg("phi_deg") = 0.0f, py::arg("wavelengths") = py::none(),
          "As BarbuleBSDF's; TRT is 0");

  m.def("presets", [] {
    py::dict d;
    for (const BarbulePreset& p : barbulePresets()) {
      py::dict v;
      v["b"] = decimal(p.b), v["phi_0"] = decimal(p.phi0), v["phi_1"] = decimal(p.phi1), v["mu"] = decimal(p.mu);
      v["H"] = decimal(p.H), v["height"] = decimal(p.height);
      v["source"] = p.source;
      d[p.name] = v;
    }
    return d;
  });
  m.def(
      "direction",
      [](float theta, float phi) {
        Vec3 v = directionFromAngles(degToRad(theta), degToRad(phi));
        return py::array_t<float>(3, &v.x);
      },
      py::arg("theta_deg"), py::arg("phi_deg") = 0.0f,
      "Unit direction at polar angle theta_deg from the vane normal and azimuth phi_deg from x (degrees)");

  m.def("_multilayer", &multilayer, py::arg("theta_deg"), py::arg("wavelength"), py::arg("layers"),
        py::arg("n_outside"), py::arg("substrate_ior"));
  m.def("_thin_film", &thinFilm, py::arg("theta_deg"), py::arg("wavelength"), py::arg("thickness"), py::arg("film_ior"),
        py::arg("n_outside"), py::arg("substrate_ior"));
  m.def("_ior", [](const py::object& index, const FloatArray& lambdas) {
    RefractiveIndex n = indexFrom(index, "ior");
    py::array_t<float> out(lambdas.size());
    for (py::ssize_t i = 0; i < lambdas.size(); ++i) out.mutable_data()[i] = n(lambdas.data()[i]);
    return out;
  });
  m.def("melanin_reflectance", py::vectorize(melaninReflectance), py::arg("wavelengths"),
        "Intensity reflectance of the melanin layer (measured table)");
  m.def("fresnel", py::vectorize(fresnelDielectric), py::arg("cos_i"), py::arg("eta"),
        "Unpolarised Fresnel reflectance of a dielectric interface (eta = n_t / n_i)");
  m.def("_fresnel_amplitudes", [](const FloatArray& cosI, const FloatArray& eta) {
    py::ssize_t n = cosI.size();
    if (eta.size() != n) throw py::value_error("the arrays must have the same length");
    std::vector<py::array_t<float>> out;
    for (int k = 0; k < 5; ++k) out.emplace_back(n);
    py::array_t<bool> tir(n);
    for (py::ssize_t i = 0; i < n; ++i) {
      FresnelAmplitudes a = fresnelAmplitudes(cosI.data()[i], eta.data()[i]);
      float v[5] = {a.rs, a.rp, a.ts, a.tp, a.cosT};
      for (int k = 0; k < 5; ++k) out[size_t(k)].mutable_data()[i] = v[k];
      tir.mutable_data()[i] = a.totalInternalReflection;
    }
    py::dict d;
    const char* names[] = {"rs", "rp", "ts", "tp", "cos_t"};
    for (int k = 0; k < 5; ++k) d[names[k]] = out[size_t(k)];
    d["total_internal_reflection"] = tir;
    return d;
  });

  m.def("_generate_feathers",
        [](const std::string& path, bool neck, int feathers, int barbs, uint64_t seed, bool binary, float height,
           float purpleHeight, float heightSpread, float purpleBelow, float colourBlend, int purpleStack) {
          FeatherGenerationOptions o;
          o.neck = neck, o.feathers = feathers, o.barbsPerSide = barbs, o.seed = seed, o.binary = binary;
          o.greenHeight = height, o.purpleHeight = purpleHeight, o.heightSpread = heightSpread;
          o.purpleBelow = purpleBelow, o.colourBlend = colourBlend, o.purpleStack = purpleStack;
          FeatherGenerationSummary s;
          try {
            py::gil_scoped_release release;
            s = generateFeatherPly(o, path);
          } catch (const std::invalid_argument& e) {
            throw py::value_error(e.what());
          }
          py::dict d;
          d["feathers"] = s.feathers, d["barbs"] = s.barbs, d["faces"] = s.faces, d["vertices"] = s.vertices;
          d["tiling_barb_width"] = s.tilingBarbWidth;
          return d;
        });
  m.def("read_feather_ply", &featherPly, py::arg("path"),
        "A feather PLY's barbs: positions and normals (B x 64 x 3), H, mu, height (B x 64, file convention) "
        "and the recorded barb width");
  m.attr("BARB_VERTICES") = kBarbVertices;
  m.attr("GREEN_CORTEX_THICKNESS") = kGreenCortexThickness;
  m.attr("PURPLE_CORTEX_THICKNESS") = kPurpleCortexThickness;
  m.attr("PURPLE_BELOW") = NeckColouring::kDefaultBoundary;
  m.attr("COLOUR_BLEND") = NeckColouring::kDefaultBlend;
  m.def("_write_feather_ply", &writeFeatherPlyArrays);
}

}  // namespace columba::python
