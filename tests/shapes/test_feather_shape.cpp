#include <gtest/gtest.h>

#include "support/feather_test_util.h"

using namespace columba;
using namespace columba::test;

namespace {

FeatherShapeParams tiltedPlacement() {
  FeatherShapeParams params;
  params.toWorld = Transform::translate(Vec3(0.08f, -0.02f, 0.01f)) *
                   Transform::rotate(normalize(Vec3(1, 2, 0.5f)), 35.0f) * Transform::scale(Vec3(0.1f, 0.1f, 0.1f));
  return params;
}

// A ray from `from` toward `to`, starting at distance `dist` before it.
Ray rayToward(const Vec3& target, const Vec3& dirTowardSource, float dist) {
  return Ray{target + dirTowardSource * dist, -dirTowardSource};
}

}  // namespace

TEST(BarbStrip, TransportedNormalsFollowAPlanarVane) {
  // Barbs curving within the plane z = 0 under a constant vane normal: nothing to twist.
  FeatherPlyData ply = syntheticBarbs(2, 1.0f, 0.0f, 0.0f);
  for (Vec3& n : ply.normals) n = Vec3(0, 0, 1);
  FeatherShape shape(std::move(ply), FeatherShapeParams());
  for (size_t prim = 0; prim < shape.primitiveCount(); ++prim) {
    BarbStrip s = shape.strip(prim);
    EXPECT_NEAR(s.n.z, 1.0f, 1e-5f) << prim;
    EXPECT_NEAR(dot(s.n, s.axis), 0.0f, 1e-5f) << prim;
  }
}

TEST(BarbStrip, ConsecutiveStripsShareTheirMitreCurve) {
  FeatherShape shape(syntheticBarbs(1, 1.5f, 0.8f, 0.15f), FeatherShapeParams());
  for (int i = 0; i + 1 < kBarbSegments; ++i) {
    BarbStrip a = shape.strip(i), b = shape.strip(i + 1);
    for (float w : {-0.99f, -0.5f, 0.0f, 0.3f, 0.99f}) {
      float angle = w * std::asin(a.halfWidthEnd / a.radius);
      // The point of strip a's end cut at this angle, then strip b's start cut at the same angle.
      auto cut = [&](const BarbStrip& s, const Vec3& plane, const Vec3& through) {
        Vec3 off = s.point(0.0f, angle) - through;
        float along = -dot(off, plane) / dot(s.axis, plane);
        return s.point(along / s.length, angle);
      };
      Vec3 pa = cut(a, a.endMitre, a.p0 + a.axis * a.length);
      Vec3 pb = cut(b, b.startMitre, b.p0);
      EXPECT_LT(length(pa - pb), 1e-6f) << "joint " << i << " angle " << angle;
    }
  }
}

TEST(BarbStrip, BoundsContainTheWholeStrip) {
  // Sharp zigzags: long mitre cuts, far from square.
  FeatherShape shape(syntheticBarbs(2, 1.5f, 0.8f, 0.4f), tiltedPlacement());
  PCG32 rng(13);
  for (size_t prim = 0; prim < shape.primitiveCount(); ++prim) {
    BarbStrip s = shape.strip(prim);
    Vec3 lo, hi;
    s.bounds(lo, hi);
    Vec3 end = s.p0 + s.axis * s.length;
    for (int k = 0; k < 200; ++k) {
      // A point of the strip: across its width, then anywhere between its two cut curves.
      float maxAngle = std::asin(std::max(s.halfWidthStart, s.halfWidthEnd) / s.radius);
      float angle = (k < 2 ? (k ? 1.0f : -1.0f) : 2.0f * rng.nextFloat() - 1.0f) * maxAngle;
      auto cutAxial = [&](const Vec3& plane, const Vec3& through) {
        return -dot(s.point(0.0f, angle) - through, plane) / dot(s.axis, plane) / s.length;
      };
      float from = cutAxial(s.startMitre, s.p0), to = cutAxial(s.endMitre, end);
      float axial = lerp(k % 3 == 0 ? float(k % 2) : rng.nextFloat(), from, to);
      float halfWidth = lerp(clampf(axial, 0.0f, 1.0f), s.halfWidthStart, s.halfWidthEnd);
      if (std::abs(s.radius * std::sin(angle)) > halfWidth) continue;  // beyond the taper
      Vec3 p = s.point(axial, angle);
      EXPECT_TRUE(p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z)
          << "primitive " << prim << ", angle " << angle << ", axial " << axial;
    }
  }
}

TEST(FeatherShape, EmbreeHitsMatchAnIndependentReference) {
  FeatherShape shape(syntheticBarbs(3, 1.2f, 0.6f, 0.12f), tiltedPlacement());
  EmbreeScene scene(shape);
  PCG32 rng(7);
  int compared = 0, mismatches = 0, hits = 0;
  for (int i = 0; i < 4000; ++i) {
    // Half the rays aim at a random point of a random strip, half at its bounding region.
    BarbStrip s = shape.strip(rng.nextUInt() % shape.primitiveCount());
    float angle = (2.0f * rng.nextFloat() - 1.0f) * 1.1f * std::asin(s.halfWidthStart / s.radius);
    Vec3 target = s.point(1.2f * rng.nextFloat() - 0.1f, angle);
    if (i % 2) target = target + randomUnitVector(rng) * (0.5f * s.radius);
    Vec3 toSource = randomUnitVector(rng);
    Ray ray = rayToward(target, toSource, 0.05f);
    auto ref = nearestReferenceHit(shape, ray.o, ray.d);
    auto got = scene.intersect(ray);
    ++compared;
    if (ref) ++hits;
    bool agree = ref.has_value() == got.has_value();
    if (agree && ref) agree = std::abs(ref->t - got->first.t) < 1e-5 * ref->t && ref->primID == got->first.primID;
    if (!agree) ++mismatches;
  }
  EXPECT_GT(hits, compared / 3);
  // Float and double can disagree on rays grazing a strip's edge; nothing else may differ.
  EXPECT_LE(mismatches, compared / 1000) << mismatches << " of " << compared;
}

TEST(FeatherShape, OccludedAgreesWithIntersect) {
  FeatherShape shape(syntheticBarbs(2, 1.0f, 0.3f, 0.1f), tiltedPlacement());
  EmbreeScene scene(shape);
  PCG32 rng(3);
  for (int i = 0; i < 500; ++i) {
    BarbStrip s = shape.strip(rng.nextUInt() % shape.primitiveCount());
    Ray ray = rayToward(s.point(rng.nextFloat(), 0.3f * (rng.nextFloat() - 0.5f)), randomUnitVector(rng), 0.02f);
    ASSERT_EQ(scene.occluded(ray), scene.intersect(ray).has_value());
  }
}

TEST(FeatherShape, RayPacketsAgreeWithSingleRays) {
  FeatherShape shape(syntheticBarbs(2, 1.0f, 0.3f, 0.1f), tiltedPlacement());
  EmbreeScene scene(shape);
  PCG32 rng(17);
  int hits = 0;
  for (int packet = 0; packet < 250; ++packet) {
    std::array<Ray, 4> rays;
    for (Ray& ray : rays) {
      BarbStrip s = shape.strip(rng.nextUInt() % shape.primitiveCount());
      Vec3 target = s.point(rng.nextFloat(), 0.5f * (rng.nextFloat() - 0.5f));
      ray = rayToward(target + randomUnitVector(rng) * (0.3f * s.radius), randomUnitVector(rng), 0.02f);
    }
    auto packed = scene.intersect4(rays);
    for (size_t i = 0; i < rays.size(); ++i) {
      auto single = scene.intersect(rays[i]);
      ASSERT_EQ(packed[i].second != RTC_INVALID_GEOMETRY_ID, single.has_value())
          << "packet " << packet << ", ray " << i;
      if (!single) continue;
      ++hits;
      EXPECT_EQ(packed[i].first, single->first.t);
      EXPECT_EQ(packed[i].second, single->first.primID);
    }
  }
  EXPECT_GT(hits, 250);
}

TEST(FeatherShape, RaysThroughMitreJointsHitOnceWithoutGap) {
  FeatherShape shape(syntheticBarbs(1, 1.5f, 0.8f, 0.15f), tiltedPlacement());
  EmbreeScene scene(shape);
  PCG32 rng(11);
  int aimed = 0;
  for (int i = 0; i + 1 < kBarbSegments; ++i) {
    BarbStrip s = shape.strip(i);
    for (int k = 0; k < 25; ++k) {
      // A point exactly on the joint's cut curve, inside the serrated band (whose teeth leave
      // gaps by design).
      float angle = (2.0f * rng.nextFloat() - 1.0f) * 0.939f * std::asin(s.halfWidthEnd / s.radius);
      Vec3 end = s.p0 + s.axis * s.length;
      Vec3 off = s.point(0.0f, angle) - end;
      Vec3 target = s.point(-dot(off, s.endMitre) / dot(s.axis, s.endMitre) / s.length, angle);
      // From above the strip, within 40 degrees of its normal there, so the ray leaves the
      // cylinder through its lower half after crossing the strip.
      Frame local = Frame::fromNormal(s.normal(angle));
      float c = 1.0f - rng.nextFloat() * (1.0f - std::cos(0.7f)), ph = kTwoPi * rng.nextFloat();
      float sn = safeSqrt(1.0f - c * c);
      Vec3 toSource = local.toWorld(Vec3(sn * std::cos(ph), sn * std::sin(ph), c));
      const float dist = 0.03f;
      Ray ray = rayToward(target, toSource, dist);
      auto hit = scene.intersect(ray);
      ++aimed;
      ASSERT_TRUE(hit.has_value()) << "gap at joint " << i << ", angle " << angle;
      EXPECT_NEAR(hit->first.t, dist, 2e-5f * dist) << "joint " << i;
      EXPECT_TRUE(hit->first.primID == unsigned(i) || hit->first.primID == unsigned(i + 1));
      // Continuing through the strip, as a pass-through does, must not meet it again.
      auto again = scene.intersect(hit->second.spawnRay(ray.d));
      EXPECT_FALSE(again.has_value()) << "double hit at joint " << i << ", t " << again->first.t;
    }
  }
  EXPECT_EQ(aimed, 25 * (kBarbSegments - 1));
}

TEST(FeatherShape, SpawnedRaysDoNotReHitTheirStrip) {
  FeatherShape shape(syntheticBarbs(2, 1.0f, 0.3f, 0.1f), tiltedPlacement());
  EmbreeScene scene(shape);
  PCG32 rng(5);
  for (int i = 0; i < 2000; ++i) {
    BarbStrip s = shape.strip(rng.nextUInt() % shape.primitiveCount());
    Vec3 target =
        s.point(rng.nextFloat(), 0.9f * (2.0f * rng.nextFloat() - 1.0f) * std::asin(s.halfWidthEnd / s.radius));
    Vec3 toSource = randomUnitVector(rng);
    if (dot(toSource, s.normal(0.0f)) < 0.2f) continue;
    auto hit = scene.intersect(rayToward(target, toSource, 0.03f));
    ASSERT_TRUE(hit.has_value());
    // Leave toward the outer side (reflection): the convex strip cannot be met again.
    Vec3 out = hit->second.shading.toWorld(normalize(Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 0.2f)));
    auto again = scene.intersect(hit->second.spawnRay(out));
    // Other parts of the curved barbs may be hit, but not the spot the ray left.
    if (again) {
      EXPECT_GT(again->first.t, 0.05f * shape.radius()) << "self-intersection";
    }
  }
}

TEST(FeatherShape, ShadingFramesFollowTheBarbules) {
  FeatherShapeParams params = tiltedPlacement();
  params.span = 0.45f;
  params.ramusWidth = 0.002f;
  FeatherShape shape(syntheticBarbs(2, 1.0f, 0.5f, 0.1f), params);
  EmbreeScene scene(shape);
  PCG32 rng(9);
  int ramusHits = 0, barbuleHits = 0;
  for (int i = 0; i < 1000; ++i) {
    size_t prim = rng.nextUInt() % shape.primitiveCount();
    BarbStrip s = shape.strip(prim);
    float along = 0.3f + 0.4f * rng.nextFloat();  // clear of the mitre cuts
    // Inside the serrated band's inner edge, so that every aimed ray hits.
    float angle = (2.0f * rng.nextFloat() - 1.0f) * 0.93f * std::asin(s.halfWidthEnd / s.radius);
    Vec3 target = s.point(along, angle);
    Vec3 toSource = normalize(s.normal(angle) + randomUnitVector(rng) * 0.3f);
    auto hitP = scene.intersect(rayToward(target, toSource, 0.02f));
    // The mirror image of that ray in the plane of the barb axis and the strip normal.
    Vec3 toSourceMirrored = toSource - 2.0f * dot(toSource, s.b) * s.b;
    auto hitM = scene.intersect(rayToward(s.point(along, -angle), toSourceMirrored, 0.02f));
    ASSERT_TRUE(hitP && hitM);
    ASSERT_EQ(hitP->first.primID, prim);
    const SurfaceInteraction& si = hitP->second;
    const Frame& f = si.shading;
    EXPECT_NEAR(length(si.p - target), 0.0f, 1e-6f);
    EXPECT_NEAR(length(f.s), 1.0f, 1e-5f);
    EXPECT_NEAR(length(f.t), 1.0f, 1e-5f);
    EXPECT_NEAR(length(f.n), 1.0f, 1e-5f);
    EXPECT_NEAR(dot(f.s, f.t), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(f.s, f.n), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(f.t, f.n), 0.0f, 1e-5f);
    EXPECT_NEAR(length(cross(f.t, f.n) - f.s), 0.0f, 1e-5f);
    EXPECT_NEAR(length(f.n - si.ng), 0.0f, 1e-6f);
    EXPECT_GT(dot(si.ng, s.n), 0.6f);  // the outer side
    if (shape.onRamus(si)) {
      ++ramusHits;
      EXPECT_NEAR(dot(f.t, s.axis), 1.0f, 1e-5f);
      continue;
    }
    ++barbuleHits;
    // The barbule line leaves the ramus toward the tip: t is along it, toward the tip on the
    // negative side and back toward the ramus on the positive side (s toward the ramus on both).
    const float sense = angle > 0.0f ? -1.0f : 1.0f;
    EXPECT_NEAR(dot(f.t, s.axis) * sense, std::cos(params.span), 1e-5f);
    EXPECT_GT(dot(f.t * sense, s.b) * angle, 0.0f);
    // The other side's barbule line is the mirror image in the plane of the axis and the normal.
    ASSERT_EQ(hitM->first.primID, prim);
    Vec3 t = f.t, mirrored = t - 2.0f * dot(t, s.b) * s.b;
    EXPECT_NEAR(length(mirrored + hitM->second.shading.t), 0.0f, 1e-4f);
  }
  EXPECT_GT(ramusHits, 5);
  EXPECT_GT(barbuleHits, 500);
}

TEST(FeatherShape, PerVertexParametersAreInterpolatedAlongTheBarb) {
  FeatherShape shape(syntheticBarbs(1, 0.5f, 0.0f, 0.0f), FeatherShapeParams());
  EmbreeScene scene(shape);
  for (int seg : {0, 20, 62}) {
    BarbStrip s = shape.strip(seg);
    // Clear of the ramus tilt zone (0.1 of the half-angle) and of the serrated band.
    const float angle = 0.5f * std::asin(s.halfWidthEnd / s.radius);
    for (float along : {0.25f, 0.75f}) {
      auto hit = scene.intersect(rayToward(s.point(along, angle), s.normal(angle), 0.02f));
      ASSERT_TRUE(hit.has_value());
      float pos = (float(seg) + along) / float(kBarbSegments);  // syntheticBarbs: file H = 1 + pos
      EXPECT_NEAR(hit->second.uv.x, pos, 1e-4f);
      EXPECT_NEAR(attribute(hit->second, "H"), 2.5f * (1.0f + pos), 1e-4f);
      EXPECT_NEAR(attribute(hit->second, "mu"), 0.35f, 1e-6f);  // file mu -0.35
      EXPECT_NEAR(attribute(hit->second, "height"), 0.6f - 0.1f * pos, 1e-4f);
    }
  }
}

TEST(FeatherShape, WidthsScaleWithTheTransformAndTaperTowardTheTip) {
  FeatherShapeParams params;
  params.barbWidth = 0.02f;
  params.cover = 0.6f;
  params.toWorld = Transform::scale(Vec3(0.5f, 0.5f, 0.5f));
  FeatherShape shape(syntheticBarbs(1, 0.0f, 0.0f, 0.0f), params);
  EXPECT_NEAR(shape.radius(), 0.5f * 0.01f / std::sin(0.6f), 1e-7f);
  BarbStrip base = shape.strip(0), tip = shape.strip(kBarbSegments - 1);
  EXPECT_NEAR(base.halfWidthStart, 0.005f, 1e-8f);
  EXPECT_NEAR(tip.halfWidthEnd, 0.005f * FeatherShape::kTipWidthFraction, 1e-8f);
}

TEST(FeatherShape, RejectsDegenerateBarbs) {
  FeatherPlyData dup = syntheticBarbs(2, 0.5f, 0.0f, 0.0f);
  dup.positions[kBarbVertices + 5] = dup.positions[kBarbVertices + 4];
  try {
    FeatherShape shape(std::move(dup), FeatherShapeParams());
    FAIL() << "a zero-length segment was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("face 1"), std::string::npos) << e.what();
  }
  FeatherPlyData folded = syntheticBarbs(1, 0.0f, 0.0f, 0.0f);
  folded.positions[10] = folded.positions[8];
  EXPECT_THROW(FeatherShape(std::move(folded), FeatherShapeParams()), InputError);
}

TEST(FeatherShape, AHitChoosesTheLayerStackOfTheNearerVertex) {
  FeatherPlyData ply = syntheticBarbs(1, 0.5f, 0.0f, 0.0f);
  for (int k = 0; k < kBarbVertices; ++k) ply.layerStack.push_back(uint8_t(k % 3));
  ply.largestLayerStack = 2;
  FeatherShape shape(std::move(ply), FeatherShapeParams());
  EmbreeScene scene(shape);
  for (int seg : {0, 20, 61, 62}) {
    BarbStrip s = shape.strip(seg);
    const float angle = 0.5f * std::asin(s.halfWidthEnd / s.radius);
    for (float along : {0.2f, 0.45f, 0.55f, 0.8f}) {
      auto hit = scene.intersect(rayToward(s.point(along, angle), s.normal(angle), 0.02f));
      ASSERT_TRUE(hit.has_value());
      const int nearer = seg + (along < 0.5f ? 0 : 1);
      EXPECT_EQ(attribute(hit->second, "stack"), float(nearer % 3)) << "segment " << seg << ", along " << along;
    }
  }
  // A feather without stacks gives none.
  FeatherShape plain(syntheticBarbs(1, 0.5f, 0.0f, 0.0f), FeatherShapeParams());
  EmbreeScene plainScene(plain);
  BarbStrip s = plain.strip(5);
  auto hit = plainScene.intersect(rayToward(s.point(0.5f, 0.0f), s.normal(0.0f), 0.02f));
  ASSERT_TRUE(hit.has_value());
  EXPECT_TRUE(std::isnan(attribute(hit->second, "stack")));
}
