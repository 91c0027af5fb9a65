#include "optics/multilayer.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace columba {

namespace {
using Complex = std::complex<double>;
using Matrix = std::array<Complex, 4>;  // row-major 2 x 2

// a / b through b's conjugate and squared modulus: the indices here are of order one, far from
// where the library's scaled complex division (most of a layered film's time) guards against
// overflow.
Complex over(Complex a, Complex b) { return a * std::conj(b) * (1.0 / std::norm(b)); }

Matrix multiply(const Matrix& a, const Matrix& b) {
  return {a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3]};
}

// n cos(theta) in a medium of index n for light whose tangential wave-vector component is
// n0 sin(theta0), on the branch of a wave that travels or decays away from the incident side.
Complex normalComponent(Complex n, double tangential) {
  Complex q = std::sqrt(n * n - tangential * tangential);
  if (q.imag() < 0.0 || (q.imag() == 0.0 && q.real() < 0.0)) q = -q;
  return q;
}

// Tilted admittances (in units of free space's) for s and p: n cos(theta) and n / cos(theta) =
// n^2 / (n cos(theta)).
struct Admittance {
  Complex s, p;
};
Admittance admittance(Complex n, Complex q) { return {q, over(n * n, q)}; }

// A product of layer matrices, per polarisation, kept as e^logScale times `m`. Each layer's matrix
// is divided by e^b, b = Im(delta) >= 0 (the wave decays along the branch chosen), and a product
// whose entries leave [1e-50, 1e50] in modulus is divided by its largest: R does not change with
// a common factor, and T takes it back (divided by e^(2 logScale)). An absorbing layer however
// thick, thousands of absorbing layers, or many periods deep in a band gap at grazing incidence
// (where the entries grow as a power of the periods) then neither overflow nor underflow.
struct ScaledMatrix {
  Matrix m{1.0, 0.0, 0.0, 1.0};
  double logScale = 0.0;
};

ScaledMatrix product(const ScaledMatrix& a, const ScaledMatrix& b) {
  ScaledMatrix r{multiply(a.m, b.m), a.logScale + b.logScale};
  double largest = 0.0;
  for (const Complex& v : r.m) largest = std::max(largest, std::norm(v));
  // Moduli kept within 1e-50 to 1e50: a product of two such matrices stays far from overflow, and
  // so do the squared moduli compared here.
  if (largest > 1e100 || (largest < 1e-100 && largest > 0.0)) {
    const double scale = std::sqrt(largest);
    for (Complex& v : r.m) v /= scale;
    r.logScale += std::log(scale);
  }
  return r;
}

// The products of the matrices of `count` layers from `first`, s and p. A layer's phase thickness,
// and so its cosine and sine, is the same for s and p: computed once for both.
struct RunMatrices {
  ScaledMatrix s, p;
};
RunMatrices runMatrices(const Layer* first, size_t count, double tangential, double lambdaNm) {
  RunMatrices m;
  const Complex minusI(0.0, -1.0);
  for (const Layer* layerPointer = first; layerPointer != first + count; ++layerPointer) {
    const Layer& layer = *layerPointer;
    const Complex q = normalComponent(layer.index, tangential);
    const Complex delta = 2.0 * M_PI / lambdaNm * (layer.thicknessUm * 1000.0) * q;
    const Admittance e = admittance(layer.index, q);
    // cos(a + ib) = cos a cosh b - i sin a sinh b, sin(a + ib) = sin a cosh b + i cos a sinh b,
    // here divided by e^b: one sine, cosine and exponential where the library's complex functions
    // take two of each.
    const double cosA = std::cos(delta.real()), sinA = std::sin(delta.real());
    const double decaySqr = std::exp(-2.0 * delta.imag());
    const double coshB = 0.5 * (1.0 + decaySqr), sinhB = 0.5 * (1.0 - decaySqr);
    const Complex c(cosA * coshB, -sinA * sinhB), sn(sinA * coshB, cosA * sinhB);
    // With indices n + ik (time dependence e^{-i omega t}, Born & Wolf's convention) the layer's
    // matrix carries -i; Macleod's +i goes with n - ik.
    m.s = product(m.s, {{c, over(minusI * sn, e.s), minusI * e.s * sn, c}, delta.imag()});
    m.p = product(m.p, {{c, over(minusI * sn, e.p), minusI * e.p * sn, c}, delta.imag()});
  }
  return m;
}

// M^times by squaring.
ScaledMatrix power(ScaledMatrix m, int times) {
  ScaledMatrix result;
  for (; times > 0; times >>= 1) {
    if (times & 1) result = product(result, m);
    if (times > 1) m = product(m, m);
  }
  return result;
}

// R and T of both polarisations from the stack's [B, C] = M [1, eta_substrate], for light whose
// tangential wave-vector component is `tangential`. Nothing is allocated: the lobes of a layered
// barbule film call this at every quadrature node.
void response(const LayerStack& stack, double tangential, double lambdaNm, MultilayerResponse& r) {
  const double n0 = stack.incidentIndex;
  ScaledMatrix ms, mp;
  const LayerRun everyLayerOnce{stack.layers.size(), 1};
  const LayerRun* run = stack.runs.empty() ? &everyLayerOnce : stack.runs.data();
  const LayerRun* end = stack.runs.empty() ? &everyLayerOnce + 1 : stack.runs.data() + stack.runs.size();
  for (const Layer* first = stack.layers.data(); run != end; first += run->count, ++run) {
    const RunMatrices m = runMatrices(first, run->count, tangential, lambdaNm);
    ms = product(ms, run->times == 1 ? m.s : power(m.s, run->times));
    mp = product(mp, run->times == 1 ? m.p : power(m.p, run->times));
  }
  const Admittance eta0 = admittance(n0, normalComponent(n0, tangential));
  const Admittance etaS = admittance(stack.substrateIndex, normalComponent(stack.substrateIndex, tangential));
  auto finish = [](const ScaledMatrix& scaled, Complex incident, Complex substrate, double& R, double& T) {
    const Matrix& m = scaled.m;
    const Complex B = m[0] + m[1] * substrate, C = m[2] + m[3] * substrate;
    const double denominator = std::norm(incident * B + C);
    R = std::norm(incident * B - C) / denominator;
    T = 4.0 * incident.real() * substrate.real() / denominator * std::exp(-2.0 * scaled.logScale);
  };
  finish(ms, eta0.s, etaS.s, r.rs, r.ts);
  finish(mp, eta0.p, etaS.p, r.rp, r.tp);
}
}  // namespace

MultilayerResponse multilayerResponse(const LayerStack& stack, double thetaIncident, double lambdaNm) {
  if (!(thetaIncident >= 0.0 && thetaIncident <= 0.5 * M_PI))
    throw std::invalid_argument(
        fmt::format("the angle of incidence {:g} degrees lies outside [0, 90]", thetaIncident * 180.0 / M_PI));
  if (!(lambdaNm > 0.0 && std::isfinite(lambdaNm)))
    throw std::invalid_argument(fmt::format("the wavelength {:g} nm is not positive and finite", lambdaNm));
  auto check = [](Complex n, const char* what) {
    if (!(n.real() > 0.0) || n.imag() < 0.0 || !std::isfinite(n.real()) || !std::isfinite(n.imag()))
      throw std::invalid_argument(std::string(what) +
                                  ": an index needs a positive real and a non-negative imaginary part");
  };
  check(stack.incidentIndex, "the incident medium");
  check(stack.substrateIndex, "the substrate");
  for (const Layer& layer : stack.layers) {
    check(layer.index, "a layer");
    if (!(layer.thicknessUm >= 0.0)) throw std::invalid_argument("a layer's thickness must not be negative");
  }
  size_t covered = 0;
  for (const LayerRun& run : stack.runs) {
    if (run.times < 1) throw std::invalid_argument("a run of layers repeats at least once");
    covered += run.count;
  }
  if (!stack.runs.empty() && covered != stack.layers.size())
    throw std::invalid_argument("the runs of layers must cover the stack's layers");
  MultilayerResponse r;
  const double tangential = stack.incidentIndex * std::sin(thetaIncident);
  if (tangential == stack.incidentIndex) {  // grazing: the incident admittances are 0 (s) and infinite (p)
    r.rs = r.rp = 1.0;
    return r;
  }
  response(stack, tangential, lambdaNm, r);
  return r;
}

LayerStack reversed(const LayerStack& stack) {
  if (stack.substrateIndex.imag() != 0.0)
    throw std::invalid_argument("a stack is seen from its substrate's side only through a transparent substrate");
  LayerStack back;
  back.incidentIndex = stack.substrateIndex.real();
  back.layers.assign(stack.layers.rbegin(), stack.layers.rend());
  back.runs.assign(stack.runs.rbegin(), stack.runs.rend());  // a run reversed repeats its reverse
  back.substrateIndex = stack.incidentIndex;
  return back;
}

}  // namespace columba
