#include "barbule/parameter_reader.h"

#include <stdexcept>

#include "barbule/layer_stacks.h"
#include "optics/dispersion.h"
#include "optics/film_layer_text.h"

namespace columba {

namespace {

// A <float>, a <string> with a number, a named index or "keratin", or (`tabulated`) a <spectrum>
// of the index against wavelength.
RefractiveIndex readIOR(const Properties& props, const std::string& name, const std::string& defaultName,
                        bool tabulated) {
  if (props.has(name) && !props.isString(name)) {
    SpectralDistribution n = tabulated ? props.getSpectrum(name, 1.0f, SpectrumUse::Unbounded)
                                       : SpectralDistribution::constant(props.getFloat(name));
    if (!n.isConstant()) return RefractiveIndex::tabulated(std::move(n));
    float value = n.eval(kLambdaMin);
    if (!(value > 0.0f)) throw props.error(name, "the index of refraction must be positive");
    return RefractiveIndex::constant(value);
  }
  std::string text = props.getString(name, defaultName);
  std::optional<RefractiveIndex> ior = iorFromName(text);
  if (!ior)
    throw props.error(name, "unknown index of refraction '" + text +
                                "' (give a number, a named material such as 'air', or 'keratin')");
  return *ior;
}

// The layers of parameter `name` (a stack's name or its layers).
FilmStack readLayerStack(const Properties& props, const std::string& name) {
  try {
    return parseFilmLayers(expandLayerStack(props.getString(name)));
  } catch (const std::invalid_argument& e) {
    throw props.error(name, e.what());
  }
}

}  // namespace

BarbuleParameters readBarbuleParameters(const Properties& props, std::optional<BarbuleParameterProblem>& implausible) {
  BarbuleParameters p;
  if (props.has("preset")) {
    std::string name = props.getString("preset");
    std::optional<BarbuleParameters> preset = barbulePreset(name);
    if (!preset) throw props.error("preset", "unknown preset '" + name + "' (known: " + barbulePresetNames() + ")");
    p = *preset;
  }
  p.b = props.getFloat("b", p.b);
  p.phi0 = props.getFloat("phi_0", p.phi0);
  p.phi1 = props.getFloat("phi_1", p.phi1);
  p.mu = props.getFloat("mu", p.mu);
  p.H = props.getFloat("H", p.H);
  p.profileExponent = props.getFloat("profile_exponent", p.profileExponent);
  readBarbuleFilm(props, p);
  if (props.has("melanin")) p.melanin = props.getSpectrum("melanin", 0.0f, SpectrumUse::Unbounded);

  throwIfProblem(props, p);
  implausible = findImplausibility(p);
  return p;
}

void throwIfProblem(const Properties& props, const BarbuleParameters& p) {
  if (std::optional<BarbuleParameterProblem> problem = findProblem(p)) {
    // A film index given by Cauchy's law is named by the parameter the scene gave: b where the
    // index is too large and b was given, a otherwise.
    const bool cauchy = problem->parameter == "film_ior" && props.has("film_cauchy_a");
    const bool large = !(p.filmIOR.maximumVisible() <= kMaxFilmIndex) && props.has("film_cauchy_b");
    throw props.error(cauchy ? (large ? "film_cauchy_b" : "film_cauchy_a") : problem->parameter, problem->message);
  }
}

void readBarbuleFilm(const Properties& props, BarbuleParameters& p) {
  p.height = props.getFloat("height", p.height);
  if (props.has("film_cauchy_a") || props.has("film_cauchy_b")) {
    if (props.has("film_ior"))
      throw props.error("film_ior", "give the film's index either as film_ior or as film_cauchy_a/film_cauchy_b");
    p.filmIOR = RefractiveIndex::cauchy(props.getFloat("film_cauchy_a"), props.getFloat("film_cauchy_b", 0.0f));
  } else {
    p.filmIOR = readIOR(props, "film_ior", "keratin", true);
  }
  RefractiveIndex ext = readIOR(props, "ext_ior", "air", false);
  if (!ext.isConstant()) throw props.error("ext_ior", "the surrounding medium needs a constant index");
  p.extIOR = ext.a;
  if (props.has("layers")) p.layersBelow = readLayerStack(props, "layers");
}

std::string layerStackParameter(int index) { return index == 0 ? "layers" : "layers_" + std::to_string(index); }

std::vector<FilmStack> readNumberedLayerStacks(const Properties& props) {
  std::vector<FilmStack> stacks;
  // Numbered without gaps, so that a stack's number is its place. The literal "layers_" is how
  // scripts/plugin-docs.py sees that layers_N is read.
  for (int k = 1; k < kMaxLayerStacks; ++k) {
    if (!props.has("layers_" + std::to_string(k))) {
      for (int later = k + 1; later < kMaxLayerStacks; ++later)
        if (props.has(layerStackParameter(later)))
          throw props.error(layerStackParameter(later), "layer stacks are numbered from layers_1 without gaps, and " +
                                                            layerStackParameter(k) + " is missing");
      break;
    }
    stacks.push_back(readLayerStack(props, layerStackParameter(k)));
  }
  return stacks;
}

BarbuleQuadrature readBarbuleQuadrature(const Properties& props) {
  BarbuleQuadrature q;
  q.offsetNodes = props.getInt("trt_offsets", q.offsetNodes);
  q.thetaNodes = props.getInt("trt_angles", q.thetaNodes);
  if (q.offsetNodes < 1 || q.offsetNodes > 64)
    throw props.error("trt_offsets", "the TRT lobe's offset nodes must number 1 to 64");
  if (q.thetaNodes < 1 || q.thetaNodes > 16)
    throw props.error("trt_angles", "the TRT lobe's longitudinal nodes must number 1 to 16");
  return q;
}

}  // namespace columba
