#pragma once
// Eumelanin's complex refractive index in feather barbules, n(lambda) + i k(lambda), as Stavenga,
// Leertouwer, Osorio & Wilts (2015) derived it from the shiny occipital feathers of Lawes' parotia
// ("High refractive index of melanin in shiny occipital feathers of a bird of paradise", Light:
// Science & Applications 4, e243; DOI 10.1038/lsa.2015.16): a Cauchy law n = A + B / lambda^2 and
// an exponentially falling extinction k = a exp(-lambda / b), lambda in nm, with A = 1.648,
// B = 23,700 nm^2, a = 0.56, b = 270 nm. The paper's abstract gives n as 1.7-1.8 over the visible,
// which these numbers give (1.80 at 400 nm, 1.70 at 700 nm); docs/model.md, "Layer materials".

namespace columba {

struct MelaninIndex {
  static constexpr float kCauchyA = 1.648f, kCauchyB = 23700.0f;          // B in nm^2
  static constexpr float kExtinction = 0.56f, kExtinctionDecay = 270.0f;  // decay in nm
};

}  // namespace columba
