#pragma once
// A barbule cross-section made of flat arms joined end to end: a V, a boomerang, the three
// mirrors of Lawes' parotia's breast barbules (Stavenga et al. 2011). Unlike the ellipse and the
// superellipse of BarbuleCrossSection it need not be convex, so the light reaching it along a
// direction is not one interval of offsets: the profile shadows and masks itself. Each arm is a
// superellipse |u / b|^p + |v|^p = 1 (barbule/superellipse.h) turned by its tilt, and the arms'
// union is the barbule; its neighbours are the same union shifted by (0, +-H). Everything is
// answered by following lines through that array exactly (docs/model.md, "Cross-sections made of
// arms"):
// - translates of one convex arm are met along any line in the order of their index, so of the
//   translates whose shadow holds a line's offset only the one nearest the light can be met first;
// - the line first meets whichever arm's candidate lies nearest the light;
// - between the offsets where an arm's silhouette, an arm's tip or a crossing of two arms'
//   outlines projects, the line meets the same arm's same side, so the lit share of a period is a
//   sum over those pieces.
// Coordinates as BarbuleCrossSection's: u along the vane normal, v across the barbules, angles
// from u toward v; each arm's film-coated side is the half facing its own u axis.
#include <array>
#include <optional>
#include <vector>

#include "barbule/superellipse.h"

namespace columba {

// Most arms one cross-section takes, and the range of their tilts and semi-axes: arms nearer
// upright fold back onto their neighbours, whose outlines then coincide to rounding and cross
// thousands of times; semi-axes beyond the range leave the outline's points to rounding.
inline constexpr int kMaxBarbuleArms = 8;
inline constexpr double kMaxArmTilt = 89.0 * 3.14159265358979323846 / 180.0;
inline constexpr double kMinArmSemiAxis = 1e-4, kMaxArmSemiAxis = 100.0;

// A point of the array's outline reached along a line.
struct ArmHit {
  int arm = 0;
  Vec2d point;          // on the central barbule (translated back from the neighbour it was met on)
  Vec2d normal;         // unit outward normal
  bool coated = false;  // on the arm's film-coated side
};

// A point of an arm's coated side with a given normal.
struct ArmPoint {
  int arm = 0;
  Vec2d point;
  double radiusOfCurvature = 0.0;
};
// At most one such point per arm, held without allocating (eval asks for them at every query).
struct ArmPoints {
  std::array<ArmPoint, kMaxBarbuleArms> points{};
  int count = 0;
  const ArmPoint* begin() const { return points.data(); }
  const ArmPoint* end() const { return points.data() + count; }
};

class ArmedCrossSection {
 public:
  // Arms of semi-axes b (across the arm) and 1 (along it) and superellipse exponent p, tilted by
  // `tiltsRad` (each arm's face normal turned from u toward v), joined end to end in that order
  // along v; the whole cross-section tilted by mu. A spacing H below contact is raised to it.
  // Throws std::invalid_argument for no arms, more than kMaxBarbuleArms, a tilt beyond
  // kMaxArmTilt, b outside [kMinArmSemiAxis, kMaxArmSemiAxis], or mu or H not finite (H < 0).
  ArmedCrossSection(const std::vector<double>& tiltsRad, double b, double p, double mu, double H);

  int armCount() const { return int(arms_.size()); }
  double spacing() const { return H_; }
  // Smallest spacing at which neighbouring barbules do not overlap.
  double contactSpacing() const { return contact_; }
  // The arm's centre (the central barbule's frame).
  Vec2d armCentre(int arm) const { return arms_[size_t(arm)].centre; }

  // What a line coming from far along the unit direction d first meets, at offset h along
  // d turned by +90 degrees; nullopt where it passes between the barbules.
  std::optional<ArmHit> firstHit(Vec2d d, double h) const;
  // Whether the point p of arm `arm`'s outline (central barbule), whose outward normal faces d,
  // is reached from far along d without the line meeting the array before it.
  bool isReached(int arm, Vec2d p, Vec2d d) const;
  // The fraction of a period's width H |d_u| (the period seen along d) whose lines first meet a
  // film-coated side; d must not be parallel to the vane (d_u != 0).
  double coverage(Vec2d d) const;
  // The points of the arms' coated sides whose outward normal is the unit n, one per arm at
  // most, whether reached from anywhere or not.
  ArmPoints pointsWithNormal(Vec2d n) const;

 private:
  struct Arm {
    Vec2d centre;
    double cosTilt, sinTilt;  // of the arm's tilt plus mu
    // The outline's normal toward the neighbour at +H (local): the line through the midpoint
    // with this normal separates the arm from its own translate.
    Vec2d separatingNormal;
  };
  Vec2d toLocal(const Arm& arm, Vec2d w) const {
    return {w.x * arm.cosTilt + w.y * arm.sinTilt, -w.x * arm.sinTilt + w.y * arm.cosTilt};
  }
  Vec2d toWorld(const Arm& arm, Vec2d l) const {
    return {l.x * arm.cosTilt - l.y * arm.sinTilt, l.x * arm.sinTilt + l.y * arm.cosTilt};
  }
  // An arm's shadow seen along d, in offsets along d turned by +90 degrees: the central copy's is
  // centred at `centre` with half-width `halfWidth` (the outline is centrally symmetric), translate
  // k's is shifted by k `shift`, and `lightAbove` says whether translate k + 1 lies nearer the
  // light than translate k (d . separatingNormal > 0).
  struct Shadow {
    double centre, halfWidth, shift;
    bool lightAbove;
  };
  Shadow shadowOf(const Arm& arm, Vec2d d) const;
  // Of the translates whose shadow holds offset h (consecutive ones), the one a line meets first:
  // the one at the light's end; nullopt when none holds it, or along the vane (shift 0).
  static std::optional<double> translateMet(const Shadow& shadow, double h);
  // The translate of arm `arm` a line at offset h meets first, and where it enters it.
  struct Candidate {
    double depth;  // along d
    Vec2d localPoint;
  };
  std::optional<Candidate> candidate(int arm, Vec2d d, double h) const;
  // Whether arm `arm`'s translate k (not 0) nearest the central one on the light's side holds h.
  bool ownNeighbourShadows(int arm, Vec2d d, double h) const;

  Superellipse shape_;
  double H_, contact_;
  std::vector<Arm> arms_;
  // Points (central barbule) where two arms' outlines cross: offsets where the line's first
  // arm can change without a silhouette.
  std::vector<Vec2d> crossings_;
};

}  // namespace columba
