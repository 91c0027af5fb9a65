#include "support/reference_barbule.h"

#include <algorithm>
#include <limits>

namespace columba::reference {

GaussRule gaussLegendreRule(int n) {
  GaussRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;  // P_0, P_1, then up to P_n by Bonnet's recurrence
      for (int k = 2; k <= n; ++k) {
        double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.nodes[i] = x;
    rule.weights[i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
  }
  return rule;
}

namespace {

using Values = std::vector<double>;

double maxAbs(const Values& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// The rule on [a, b] for a function with several values.
template <typename F>
Values integrateWith(const GaussRule& rule, const F& f, double a, double b, size_t count) {
  Values sum(count, 0.0);
  double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (size_t j = 0; j < rule.nodes.size(); ++j) {
    Values v = f(mid + half * rule.nodes[j]);
    for (size_t k = 0; k < count; ++k) sum[k] += rule.weights[j] * half * v[k];
  }
  return sum;
}

// Adaptive bisection: a piece is done when its `low` and `high` rules agree to `absTol`.
template <typename F>
void integrateAdaptively(const RulePair& rules, const F& f, double a, double b, double absTol, int depth,
                         Values& total) {
  size_t count = total.size();
  Values low = integrateWith(rules.low, f, a, b, count), high = integrateWith(rules.high, f, a, b, count);
  double difference = 0.0;
  for (size_t k = 0; k < count; ++k) difference = std::max(difference, std::abs(high[k] - low[k]));
  if (difference <= absTol || depth >= 40) {
    for (size_t k = 0; k < count; ++k) total[k] += high[k];
    return;
  }
  double mid = 0.5 * (a + b);
  integrateAdaptively(rules, f, a, mid, absTol, depth + 1, total);
  integrateAdaptively(rules, f, mid, b, absTol, depth + 1, total);
}

// The integral over [cuts[0], cuts.back()], split at the cuts, to `tolerance` relative to its
// largest value (estimated first with the low rule).
template <typename F>
Values integratePieces(const RulePair& rules, const F& f, const std::vector<double>& cuts, size_t count,
                       double tolerance) {
  Values estimate(count, 0.0), total(count, 0.0);
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    Values v = integrateWith(rules.low, f, cuts[i], cuts[i + 1], count);
    for (size_t k = 0; k < count; ++k) estimate[k] += std::abs(v[k]);
  }
  double absTol = tolerance * std::max(maxAbs(estimate), std::numeric_limits<double>::min());
  for (size_t i = 0; i + 1 < cuts.size(); ++i) integrateAdaptively(rules, f, cuts[i], cuts[i + 1], absTol, 0, total);
  return total;
}

const GaussRule& longitudinalRule() {
  static const GaussRule rule = gaussLegendreRule(32);
  return rule;
}

// The range of |theta| <= thetaD where A cos(theta) + B sin(theta) > 0 (a sinusoid: over a range
// this short it has at most one zero).
bool facingRange(double A, double B, double& lo, double& hi) {
  auto f = [&](double t) { return A * std::cos(t) + B * std::sin(t); };
  lo = -kThetaD;
  hi = kThetaD;
  bool loFaces = f(lo) > 0.0, hiFaces = f(hi) > 0.0;
  if (loFaces && hiFaces) return true;
  if (!loFaces && !hiFaces) return false;
  double zero = std::atan(-A / B);
  if (loFaces)
    hi = zero;
  else
    lo = zero;
  return hi > lo;
}

}  // namespace

LongitudinalMoments longitudinalMoments(double A, double B) {
  LongitudinalMoments m;
  m.A = A;
  m.B = B;
  if (!facingRange(A, B, m.lo, m.hi)) return m;
  auto f = [&](double t) { return Values{A * std::cos(t) + B * std::sin(t), t * (A * std::cos(t) + B * std::sin(t))}; };
  Values moments = integrateWith(longitudinalRule(), f, m.lo, m.hi, 2);
  m.mass = moments[0];
  m.mean = moments[0] > 0.0 ? moments[1] / moments[0] : 0.5 * (m.lo + m.hi);
  return m;
}

BarbuleReference::BarbuleReference(const BarbuleModel& model, int baseNodes, double tolerance)
    : m_(model),
      H_(std::max(model.H, contactSpacing(model.b, model.mu))),
      wholeEllipse_(model.phi1 - model.phi0 >= 2.0 * M_PI),
      rules_{gaussLegendreRule(baseNodes), gaussLegendreRule(2 * baseNodes)},
      thetaRules_{gaussLegendreRule(baseNodes / 2), gaussLegendreRule(baseNodes)},
      tolerance_(tolerance) {}

double BarbuleReference::contactSpacing(double b, double mu) {
  // Translates K and K + w of a centrally symmetric convex K meet iff w / 2 lies in K. The
  // neighbour's offset w = (0, H) (world u, v) is H (sin mu, cos mu) in the ellipse's frame.
  return 2.0 / std::sqrt(std::sin(mu) * std::sin(mu) / (b * b) + std::cos(mu) * std::cos(mu));
}

void BarbuleReference::pointWithNormal(double phi, double& u, double& v) const {
  double b = m_.b, c = std::cos(phi), s = std::sin(phi);
  double k = 1.0 / std::sqrt(b * b * c * c + s * s);
  double pu = b * b * c * k, pv = s * k;  // own frame
  u = pu * std::cos(m_.mu) - pv * std::sin(m_.mu);
  v = pu * std::sin(m_.mu) + pv * std::cos(m_.mu);
}

double BarbuleReference::radiusOfCurvature(double phi) const {
  double b = m_.b, s = std::sin(phi), c = std::cos(phi);
  return b * b / std::pow(s * s + b * b * c * c, 1.5);
}

bool BarbuleReference::onReflectiveArc(double phi) const {
  if (wholeEllipse_) return true;
  double fromStart = std::fmod(phi - m_.phi0, 2.0 * M_PI);
  if (fromStart < 0.0) fromStart += 2.0 * M_PI;
  return fromStart <= m_.phi1 - m_.phi0;
}

bool BarbuleReference::shadowed(double phi, double gamma) const {
  double pu, pv;
  pointWithNormal(phi, pu, pv);
  double du = std::cos(gamma), dv = std::sin(gamma);
  double cm = std::cos(m_.mu), sm = std::sin(m_.mu), bb = m_.b * m_.b;
  for (int k : {-2, -1, 1, 2}) {
    // The ray p + t d, t > 0, in the frame of the neighbour centred at (0, k H).
    double ou = pu, ov = pv - k * H_;
    double lu = ou * cm + ov * sm, lv = -ou * sm + ov * cm;
    double eu = du * cm + dv * sm, ev = -du * sm + dv * cm;
    double a = eu * eu / bb + ev * ev, half = lu * eu / bb + lv * ev, c = lu * lu / bb + lv * lv - 1.0;
    double disc = half * half - a * c;
    if (disc > 0.0 && (-half + std::sqrt(disc)) / a > 0.0) return true;
  }
  return false;
}

bool BarbuleReference::lit(double phi, double gamma) const {
  return std::cos(phi + m_.mu - gamma) > 0.0 && onReflectiveArc(phi) && !shadowed(phi, gamma);
}

std::vector<AngleInterval> BarbuleReference::litNormals(double gamma) const {
  double alpha = gamma - m_.mu;
  double lo = alpha - 0.5 * M_PI, hi = alpha + 0.5 * M_PI;
  // Where being on the arc can change: its ends; in between, only shadowing changes, found by a
  // scan and bisection.
  std::vector<double> breaks = {lo, hi};
  if (!wholeEllipse_)
    for (double end : {m_.phi0, m_.phi1})
      for (int k = -3; k <= 3; ++k) {
        double e = end + 2.0 * M_PI * k;
        if (e > lo && e < hi) breaks.push_back(e);
      }
  std::sort(breaks.begin(), breaks.end());
  std::vector<AngleInterval> out;
  auto add = [&](double a, double b) {
    if (!(b > a)) return;
    if (!out.empty() && out.back().hi == a)
      out.back().hi = b;
    else
      out.push_back({a, b});
  };
  const int kScan = 256;
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    double a = breaks[i], b = breaks[i + 1];
    if (!(b > a) || !onReflectiveArc(0.5 * (a + b))) continue;
    auto open = [&](double phi) { return !shadowed(phi, gamma); };
    double runStart = a, previous = a;
    bool wasOpen = open(a);
    for (int j = 1; j <= kScan; ++j) {
      double x = j == kScan ? b : a + (b - a) * j / kScan;
      bool isOpen = open(x);
      if (isOpen != wasOpen) {
        double l = previous, r = x;
        for (int iteration = 0; iteration < 200 && r - l > 1e-15; ++iteration) {
          double mid = 0.5 * (l + r);
          (open(mid) == wasOpen ? l : r) = mid;
        }
        double edge = 0.5 * (l + r);
        if (wasOpen) add(runStart, edge);
        runStart = edge;
        wasOpen = isOpen;
      }
      previous = x;
    }
    if (wasOpen) add(runStart, b);
  }
  return out;
}

double BarbuleReference::offset(double phi, double gamma) const {
  double u, v;
  pointWithNormal(phi, u, v);
  return -u * std::sin(gamma) + v * std::cos(gamma);
}

double BarbuleReference::litWidth(double gamma) const {
  double width = 0.0;
  for (const AngleInterval& piece : litNormals(gamma)) width += offset(piece.hi, gamma) - offset(piece.lo, gamma);
  return width;
}

double BarbuleReference::litWidthByIntegral(double gamma) const {
  auto f = [&](double phi) { return Values{radiusOfCurvature(phi) * std::cos(phi + m_.mu - gamma)}; };
  double total = 0.0;
  for (const AngleInterval& piece : litNormals(gamma))
    total += integratePieces(rules_, f, {piece.lo, piece.hi}, 1, 1e-14)[0];
  return total;
}

double BarbuleReference::coverage(const Direction& w) const {
  Direction up = w.z < 0.0 ? Direction{-w.x, -w.y, -w.z} : w;
  double cosTheta = std::hypot(up.x, up.z);
  if (!(cosTheta > 0.0)) return 0.0;
  double gamma = inPlaneAngle(up);
  double period = H_ * std::abs(std::cos(gamma));
  if (!(period > 0.0)) return 0.0;
  return std::clamp(litWidth(gamma) / period, 0.0, 1.0);
}

namespace {

double sqr(double x) { return x * x; }

Direction normalised(const Direction& w) {
  double l = std::sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
  return {w.x / l, w.y / l, w.z / l};
}

// Angular distance of phi from the nearest end of the intervals.
double distanceToEnds(double phi, const std::vector<AngleInterval>& pieces) {
  double d = std::numeric_limits<double>::infinity();
  for (const AngleInterval& piece : pieces)
    for (double end : {piece.lo, piece.hi}) d = std::min(d, std::abs(std::remainder(phi - end, 2.0 * M_PI)));
  return d;
}

}  // namespace

BarbuleReference::Reflection BarbuleReference::reflection(const Direction& wiIn, const Direction& woIn,
                                                          const std::vector<double>& lambdas) const {
  Reflection r;
  r.value.assign(lambdas.size(), 0.0);
  r.envelope.assign(lambdas.size(), 0.0);
  r.phaseSensitivity.assign(lambdas.size(), 0.0);
  r.roundingSensitivity.assign(lambdas.size(), 0.0);
  r.phiMargin = r.thetaMargin = std::numeric_limits<double>::infinity();
  Direction wi = normalised(wiIn), wo = normalised(woIn);
  if (!(wi.z > 0.0) || wo.z == 0.0) return r;
  Direction m = normalised({wi.x + wo.x, wi.y + wo.y, wi.z + wo.z});
  double thetaM = std::asin(m.y);
  double phiWorld = std::atan2(m.x, m.z), phi = phiWorld - m_.mu;
  double gammaI = inPlaneAngle(wi), gammaO = inPlaneAngle(wo);
  r.thetaMargin = kThetaD - std::abs(thetaM);
  r.phiMargin = std::min(distanceToEnds(phi, litNormals(gammaI)), distanceToEnds(phi, litNormals(gammaO)));
  if (!(std::abs(thetaM) < kThetaD)) return r;
  if (!lit(phi, gammaI) || !lit(phi, gammaO)) return r;  // G = 0

  // D(m) = D_phi D_theta / cos(theta_m), D_phi = rho / H, D_theta = 1 / (2 sin thetaD).
  double D = radiusOfCurvature(phi) / H_ / (2.0 * std::sin(kThetaD)) / std::cos(thetaM);
  // Longitudinal shadowing of w at this normal, from w's projection A onto the normal's in-plane part.
  auto projection = [&](const Direction& w) { return w.z * std::cos(phiWorld) + w.x * std::sin(phiWorld); };
  auto shadowing = [&](double A, const Direction& w) { return longitudinalMoments(A, w.y).shadowing(); };
  double Ai = projection(wi), Ao = projection(wo);
  double Si = shadowing(Ai, wi), So = shadowing(Ao, wo);
  double scale = D * Si * So / (4.0 * std::abs(wi.z) * std::abs(wo.z));
  double cosHalf = wi.x * m.x + wi.y * m.y + wi.z * m.z;
  // Relative change of the geometric factor per unit absolute change of A_i, A_o, and of phi times
  // |omega_i + omega_o| (the half vector is a normalised sum: its angle errs by a rounding over that).
  auto logSlope = [](const auto& f, double x, double h) { return std::abs(f(x + h) - f(x - h)) / (2.0 * h * f(x)); };
  double geometric = logSlope([&](double A) { return shadowing(A, wi); }, Ai, std::min(1e-6, 0.5 * Ai)) +
                     logSlope([&](double A) { return shadowing(A, wo); }, Ao, std::min(1e-6, 0.5 * Ao)) +
                     logSlope([&](double p) { return radiusOfCurvature(p); }, phi, 1e-6) /
                         std::sqrt(sqr(wi.x + wo.x) + sqr(wi.y + wo.y) + sqr(wi.z + wo.z));
  for (size_t k = 0; k < lambdas.size(); ++k) {
    double n = m_.filmIndex(lambdas[k]);
    auto film = [&](double c, double phaseScale) {
      return airyFilm(c, m_.nOutside, n, m_.nOutside, m_.heightUm, lambdas[k], phaseScale).reflectance();
    };
    r.value[k] = scale * film(cosHalf, 1.0);
    r.envelope[k] = scale * freeStandingReflectanceEnvelope(cosHalf, m_.nOutside, n);
    const double h = 1e-6, dc = std::min(1e-6, 0.5 * cosHalf);
    r.phaseSensitivity[k] = scale * std::abs(film(cosHalf, 1.0 + h) - film(cosHalf, 1.0 - h)) / (2.0 * h);
    r.roundingSensitivity[k] =
        scale * std::abs(film(cosHalf + dc, 1.0) - film(cosHalf - dc, 1.0)) / (2.0 * dc) + geometric * r.value[k];
  }
  return r;
}

std::vector<AngleInterval> BarbuleReference::commonNormals(double gammaI, double gammaO) const {
  // As angles within the half facing gammaI.
  std::vector<AngleInterval> both;
  for (const AngleInterval& a : litNormals(gammaI))
    for (const AngleInterval& b : litNormals(gammaO))
      for (int k = -1; k <= 1; ++k) {
        double lo = std::max(a.lo, b.lo + 2.0 * M_PI * k), hi = std::min(a.hi, b.hi + 2.0 * M_PI * k);
        if (hi > lo) both.push_back({lo, hi});
      }
  return both;
}

double BarbuleReference::commonWidth(const Direction& wi, const Direction& wo) const {
  double gammaI = inPlaneAngle(wi), width = 0.0;
  for (const AngleInterval& piece : commonNormals(gammaI, inPlaneAngle(wo)))
    width += offset(piece.hi, gammaI) - offset(piece.lo, gammaI);
  return width;
}

BarbuleReference::TRT BarbuleReference::trt(const Direction& wiIn, const Direction& woIn,
                                            const std::vector<double>& lambdas,
                                            const std::vector<double>& melanin) const {
  TRT out;
  size_t count = lambdas.size();
  out.value.assign(count, 0.0);
  out.endDensity.assign(count, 0.0);
  Direction wi = normalised(wiIn), wo = normalised(woIn);
  if (!(wi.z > 0.0) || wo.z == 0.0) return out;
  double gammaI = inPlaneAngle(wi), gammaO = inPlaneAngle(wo), alphaI = gammaI - m_.mu;
  std::vector<AngleInterval> both = commonNormals(gammaI, gammaO);
  for (const AngleInterval& piece : both) out.commonWidth += offset(piece.hi, gammaI) - offset(piece.lo, gammaI);
  if (both.empty()) return out;

  // Split where the longitudinal range starts being clipped (|B| tan(thetaD) = A): a kink of the
  // integrand in phi.
  double cosThetaI = std::hypot(wi.x, wi.z);
  double clip = std::abs(wi.y) * std::tan(kThetaD) / cosThetaI;
  std::vector<AngleInterval> pieces;
  for (const AngleInterval& piece : both) {
    std::vector<double> cuts = {piece.lo, piece.hi};
    if (clip < 1.0)
      for (double kink : {alphaI - std::acos(clip), alphaI + std::acos(clip)})
        if (kink > piece.lo && kink < piece.hi) cuts.push_back(kink);
    std::sort(cuts.begin(), cuts.end());
    for (size_t i = 0; i + 1 < cuts.size(); ++i) pieces.push_back({cuts[i], cuts[i + 1]});
  }

  std::vector<double> nFilm(count);
  for (size_t k = 0; k < count; ++k) nFilm[k] = m_.filmIndex(lambdas[k]);
  // E_theta[I_TRT / R_m] at the normal phi: the longitudinal mean with density proportional to
  // (omega_i . m)+.
  auto meanTransmission = [&](double phi) {
    Values v(count, 0.0);
    double phiWorld = phi + m_.mu;
    double Ai = wi.z * std::cos(phiWorld) + wi.x * std::sin(phiWorld), Bi = wi.y;
    double Ao = wo.z * std::cos(phiWorld) + wo.x * std::sin(phiWorld), Bo = wo.y;
    double lo, hi;
    if (!facingRange(Ai, Bi, lo, hi)) return v;
    // (omega_i . m) and (omega_i . m) I_TRT / R_m, the mean's denominator and numerators.
    auto longitudinal = [&](double theta) {
      Values u(count + 1);
      double cosIn = Ai * std::cos(theta) + Bi * std::sin(theta);
      double cosOut = std::abs(Ao * std::cos(theta) + Bo * std::sin(theta));
      for (size_t k = 0; k < count; ++k)
        u[k] = cosIn * freeStandingTransmittanceProduct(cosIn, cosOut, m_.nOutside, nFilm[k], m_.heightUm, lambdas[k]);
      u[count] = cosIn;
      return u;
    };
    // Where omega_o . m changes sign the exit transmittance rises from 0 within a width that shrinks
    // near a resonance of the film: cut there (adaptivity resolves the rise).
    std::vector<double> cuts = {lo, hi};
    double zero = Bo != 0.0 ? std::atan(-Ao / Bo) : lo;
    if (zero > lo && zero < hi) cuts.push_back(zero);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    Values sums = integratePieces(thetaRules_, longitudinal, cuts, count + 1, tolerance_);
    double norm = sums[count];
    for (size_t k = 0; k < count; ++k) v[k] = norm > 0.0 ? sums[k] / norm : 0.0;
    return v;
  };
  // Integrated over the offsets h, dh = rho cos(gamma_i - mu - phi) dphi.
  auto integrand = [&](double phi) {
    Values v = meanTransmission(phi);
    double dh = radiusOfCurvature(phi) * std::cos(phi - alphaI);
    for (double& x : v) x *= dh;
    return v;
  };
  Values integral(count, 0.0);
  for (const AngleInterval& piece : pieces) {
    Values v = integratePieces(rules_, integrand, {piece.lo, piece.hi}, count, tolerance_);
    for (size_t k = 0; k < count; ++k) integral[k] += v[k];
  }

  // rho_TRT = R_m / (H |cos gamma_i|) * integral; f_TRT = rho_TRT / pi.
  double cosGammaI = wi.z / cosThetaI;
  for (size_t k = 0; k < count; ++k) out.value[k] = melanin[k] * integral[k] / (H_ * cosGammaI) / M_PI;
  for (const AngleInterval& piece : both)
    for (double end : {piece.lo, piece.hi}) {
      Values atEnd = meanTransmission(end);
      for (size_t k = 0; k < count; ++k) out.endDensity[k] += melanin[k] * atEnd[k] / (H_ * cosGammaI) / M_PI;
    }
  return out;
}

}  // namespace columba::reference
