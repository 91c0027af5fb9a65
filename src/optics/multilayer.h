#pragma once
// Reflectance and transmittance of a stack of plane-parallel layers by the characteristic-matrix
// (transfer-matrix) method (Born & Wolf, Principles of Optics, §1.6; Macleod, Thin-Film Optical
// Filters, ch. 2): keratin, melanin with its complex index, air gaps, melanosome layers as
// effective media. A single lossless film between equal media is the Airy film of thin_film.h.
// Derivation and conventions in docs/model.md, "Layered films".
#include <complex>
#include <vector>

namespace columba {

// One layer: its complex index n + i k (k >= 0 absorbs) and its thickness in micrometres.
struct Layer {
  std::complex<double> index;
  double thicknessUm = 0.0;
};

// Layers that repeat: the next `count` layers of a stack's list, taken `times` times in a row.
struct LayerRun {
  size_t count = 0;
  int times = 1;
};

// The stack between an incident medium (real index, where the light comes from) and a substrate
// (complex index; the light that reaches it is transmitted), layers listed from the incident side.
// `runs`, when given, cover the list in order and say how often each part repeats (a repeated
// part's matrix is raised to its power by squaring); without them each layer is taken once.
struct LayerStack {
  double incidentIndex = 1.0;
  std::vector<Layer> layers;
  std::complex<double> substrateIndex = 1.0;
  std::vector<LayerRun> runs;
};

struct MultilayerResponse {
  double rs = 0, rp = 0;  // intensity reflectance per polarisation
  double ts = 0, tp = 0;  // intensity transmittance into the substrate (0 for an evanescent wave there)
  double reflectance() const { return 0.5 * (rs + rp); }
  double transmittance() const { return 0.5 * (ts + tp); }
  // What the layers absorb: 1 - R - T per polarisation, averaged.
  double absorptance() const { return 1.0 - reflectance() - transmittance(); }
};

// The stack's response to light of vacuum wavelength `lambdaNm` meeting it at `thetaIncident`
// (radians from the normal, in the incident medium, within [0, pi/2]). At grazing incidence, pi/2,
// it is the limit R = 1, T = 0 (the incident medium's admittance is 0 for s and infinite for p).
// Throws std::invalid_argument for an angle outside [0, pi/2] or NaN, a wavelength that is not
// positive and finite, a layer of negative thickness, an index with negative real or imaginary
// part, or runs that do not cover the layers.
MultilayerResponse multilayerResponse(const LayerStack& stack, double thetaIncident, double lambdaNm);

// The same stack seen from the substrate's side (the layers in reverse, the substrate as the
// incident medium; it must be real), for reciprocity checks and light leaving a barbule.
LayerStack reversed(const LayerStack& stack);

}  // namespace columba
