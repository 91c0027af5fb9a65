// Every estimator of one image agrees, for every emitter shape under every kind of to_world
// Columba accepts: emitter sampling, BSDF sampling and their combination in `direct` and `path`,
// and the particle tracer, each render's mean luminance over seeds compared with the others'
// within kSigmas standard errors. Ray hits, area samples and their density, normals, the side
// that emits and the densities MIS uses must all describe one surface for these to agree; a
// to_world under which a shape cannot be exact must be refused instead.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/image.h"
#include "support/render_test_support.h"
#include "support/temp_dir_test.h"

using namespace columba;
using namespace columba::testing;

namespace {

constexpr double kSigmas = 4.0;
constexpr int kSeeds = 8;

struct Placement {
  const char* name;
  const char* operations;  // applied after the shape's own size, before it is turned to face the receiver
  bool similarity;         // uniform scale, no shear: the shapes that need it accept it
};

const Placement kPlacements[] = {
    {"identity", "", true},
    {"rotation", R"(<rotate x="0.6" y="0" z="0.8" angle="35"/>)", true},
    {"non-uniform scale", R"(<scale x="0.5" y="0.3" z="0.8"/>)", false},
    // An axis that is not unit length: the matrix also scales and shears (as in Mitsuba); this one
    // also turns the shape over, and the last rotation turns it back to face the receiver.
    {"shear", R"(<scale x="0.5" y="0.3" z="1"/><rotate x="1" y="1" angle="180"/><rotate x="1" angle="180"/>)", false},
    {"mirror", R"(<scale x="-0.8" y="0.8" z="0.8"/>)", true},
    {"scale, rotation, translation",
     R"(<scale x="0.6" y="0.4" z="0.5"/><rotate x="0" y="0.6" z="0.8" angle="50"/><translate x="0.2" y="-0.1" z="0.1"/>)",
     false},
};

struct EmitterShape {
  const char* name;
  const char* element;  // the <shape> up to its to_world's operations
  bool needsSimilarity;
};

const EmitterShape kShapes[] = {
    {"rectangle", R"(<shape type="rectangle"><transform name="to_world"><scale value="0.5"/>)", false},
    {"disk", R"(<shape type="disk"><transform name="to_world"><scale value="0.5"/>)", false},
    {"sphere", R"(<shape type="sphere"><float name="radius" value="0.3"/><transform name="to_world">)", true},
    {"cylinder",
     R"(<shape type="cylinder"><point name="p0" x="-0.4" y="0" z="0"/><point name="p1" x="0.4" y="0" z="0"/>
        <float name="radius" value="0.2"/><transform name="to_world">)",
     true},
    {"cube (a triangle mesh)", R"(<shape type="cube"><transform name="to_world"><scale value="0.3"/>)", false},
};

struct Estimator {
  const char* name;
  const char* integrator;
  // Whether it weighs values of the BSDF at directions it did not draw from the BSDF (emitter
  // sampling alone, the particle tracer): where those values are not square-integrable (a
  // superellipse's flat faces), its variance is infinite.
  bool evaluatesOnly;
};

// max_depth 2 everywhere: emitters seen directly and lit once, the integral `direct` computes.
const Estimator kEstimators[] = {
    {"direct, emitter sampling",
     R"(<integrator type="direct"><integer name="emitter_samples" value="1"/><integer name="bsdf_samples" value="0"/></integrator>)",
     true},
    {"direct, BSDF sampling",
     R"(<integrator type="direct"><integer name="emitter_samples" value="0"/><integer name="bsdf_samples" value="1"/></integrator>)",
     false},
    {"direct, both",
     R"(<integrator type="direct"><integer name="emitter_samples" value="1"/><integer name="bsdf_samples" value="1"/></integrator>)",
     false},
    {"path, emitter sampling",
     R"(<integrator type="path"><integer name="max_depth" value="2"/><string name="strategy" value="emitter"/></integrator>)",
     true},
    {"path, BSDF sampling",
     R"(<integrator type="path"><integer name="max_depth" value="2"/><string name="strategy" value="bsdf"/></integrator>)",
     false},
    {"path, MIS",
     R"(<integrator type="path"><integer name="max_depth" value="2"/><string name="strategy" value="mis"/></integrator>)",
     false},
    {"ptracer", R"(<integrator type="ptracer"><integer name="max_depth" value="2"/></integrator>)", true},
};

const char* const kPerspective = R"(<sensor type="perspective"><float name="fov" value="50"/>
      <transform name="to_world"><lookat origin="0, -2.2, 1.8" target="0, 0, 0.3" up="0, 0, 1"/></transform>
      <film type="hdrfilm"><integer name="width" value="12"/><integer name="height" value="12"/><rfilter type="box"/></film>
      <sampler type="independent"><integer name="sample_count" value="32"/></sampler></sensor>)";
const char* const kVisualizer = R"(<sensor type="bsdfvisualizer">
      <film type="hdrfilm"><integer name="width" value="12"/><integer name="height" value="12"/><rfilter type="box"/></film>
      <sampler type="independent"><integer name="sample_count" value="32"/></sampler></sensor>)";

const char* const kDiffuseReceiver = R"(<bsdf type="diffuse"><float name="reflectance" value="0.6"/></bsdf>)";
const char* const kBarbuleReceiver =
    R"(<bsdf type="barbulebsdf"><float name="b" value="0.25"/><float name="mu" value="-0.35"/></bsdf>)";

std::string sceneXml(const Estimator& estimator, const char* sensor, const char* receiver, const EmitterShape& shape,
                     const Placement& placement) {
  // The emitter is turned to face the receiver (its local +z down) and lifted above it.
  return std::string(R"(<scene version="3.0.0">)") + estimator.integrator + sensor +
         R"(<shape type="rectangle"><transform name="to_world"><scale value="1.2"/></transform>)" + receiver +
         "</shape>" + shape.element + placement.operations +
         R"(<rotate x="1" angle="180"/><translate z="1.1"/></transform>
           <emitter type="area"><spectrum name="radiance" value="4"/></emitter></shape></scene>)";
}

bool refused(const std::string& xml, std::string& message) {
  try {
    renderSceneString(xml, [] {
      RenderSettings s;
      s.samplesPerPixel = 1;
      return s;
    }());
    return false;
  } catch (const InputError& e) {
    message = e.what();
    return true;
  }
}

void checkAgreement(const char* sensorName, const char* sensor, const char* receiverName, const char* receiver,
                    bool withParticleTracer, bool squareIntegrable = true, bool everyPlacement = true) {
  // withParticleTracer: whether the sensor has an importance the particle tracer can reach;
  // squareIntegrable: whether the receiver's values are, so that estimators that only evaluate
  // them have a finite variance (else they are left out); everyPlacement false (and a receiver
  // that is not square-integrable): the receiver, not the transforms, is what is tested, and two
  // shapes under two placements are enough.
  for (const EmitterShape& shape : kShapes)
    for (const Placement& placement : kPlacements) {
      const std::string shapeName = shape.name, placementName = placement.name;
      if ((!squareIntegrable || !everyPlacement) && ((shapeName != "rectangle" && shapeName != "disk") ||
                                                     (placementName != "identity" && placementName != "shear")))
        continue;
      const std::string where =
          std::string(shape.name) + ", " + placement.name + ", " + receiverName + ", " + sensorName;
      if (shape.needsSimilarity && !placement.similarity) {
        // The shape would not be exact: its emitter must be refused, naming to_world.
        std::string message;
        EXPECT_TRUE(refused(sceneXml(kEstimators[0], sensor, receiver, shape, placement), message)) << where;
        EXPECT_NE(message.find("to_world"), std::string::npos) << where << ": " << message;
        continue;
      }
      std::vector<Estimate> estimates;
      std::vector<const Estimator*> used;
      for (const Estimator& estimator : kEstimators) {
        if (!squareIntegrable && estimator.evaluatesOnly) continue;
        if (!withParticleTracer && std::string(estimator.name) == "ptracer") {
          // The scatterometer has no importance to connect light paths to: refused, saying so.
          std::string message;
          EXPECT_TRUE(refused(sceneXml(estimator, sensor, receiver, shape, placement), message)) << where;
          EXPECT_NE(message.find("ptracer"), std::string::npos) << where << ": " << message;
          continue;
        }
        estimates.push_back(
            meanLuminanceOverSeeds(sceneXml(estimator, sensor, receiver, shape, placement), kSeeds, 40));
        used.push_back(&estimator);
      }
      // MIS in `direct` is the least noisy: every other estimator is held against it.
      const Estimate& reference = estimates[size_t(
          std::find_if(used.begin(), used.end(), [](const Estimator* e) { return e == &kEstimators[2]; }) -
          used.begin())];
      EXPECT_GT(reference.mean, 0.0) << where;
      for (size_t k = 0; k < estimates.size(); ++k) {
        EXPECT_LT(standardErrorsApart(estimates[k], reference), kSigmas)
            << where << ": " << used[k]->name << " " << estimates[k].mean << " +- " << estimates[k].standardError
            << " against " << reference.mean << " +- " << reference.standardError << " (ratio "
            << estimates[k].mean / reference.mean << ")";
      }
    }
}

}  // namespace

TEST(EstimatorAgreement, EveryEstimatorAgreesUnderEveryTransformInPerspectiveOnADiffuseReceiverSlow) {
  checkAgreement("perspective", kPerspective, "diffuse", kDiffuseReceiver, true);
}

TEST(EstimatorAgreement, EveryEstimatorAgreesUnderEveryTransformInPerspectiveOnABarbuleReceiverSlow) {
  checkAgreement("perspective", kPerspective, "barbule", kBarbuleReceiver, true);
}

TEST(EstimatorAgreement, EveryEstimatorWithFiniteVarianceAgreesInPerspectiveOnASquareBarbuleReceiverSlow) {
  // A superellipse cross-section: its flat faces make the normal distribution singular as
  // |phi - phi_face|^-(p-2)/(p-1) about their normals, integrable but, for p > 3, not square-
  // integrable, so the estimators that only evaluate the BSDF have an infinite variance
  // (docs/model.md, "Which estimators converge"); those that sample it must still agree.
  checkAgreement("perspective", kPerspective, "square barbule",
                 R"(<bsdf type="barbulebsdf"><float name="b" value="0.25"/><float name="mu" value="-0.35"/>
                      <float name="profile_exponent" value="8"/></bsdf>)",
                 true, /*squareIntegrable=*/false);
}

TEST(EstimatorAgreement, EveryEstimatorAgreesInPerspectiveOnABarbuleOfArmsSlow) {
  // Three arms at the parotia's angles (a roof), rounded enough (p 2.5) for every estimator's
  // variance to be finite: BSDF sampling follows lines through the barbules, emitter sampling and
  // the particle tracer only evaluate, and all see the same self-shadowing and masking.
  checkAgreement("perspective", kPerspective, "barbule of arms",
                 R"(<bsdf type="barbulearms"><string name="arm_tilts" value="-30, 0, 30"/><float name="b" value="0.2"/>
                      <float name="profile_exponent" value="2.5"/><float name="mu" value="-0.3"/></bsdf>)",
                 true, /*squareIntegrable=*/true, /*everyPlacement=*/false);
}

TEST(EstimatorAgreement, EveryEstimatorAgreesUnderEveryTransformInTheScatterometerOnADiffuseReceiverSlow) {
  checkAgreement("bsdfvisualizer", kVisualizer, "diffuse", kDiffuseReceiver, false);
}

TEST(EstimatorAgreement, EveryEstimatorAgreesUnderEveryTransformInTheScatterometerOnABarbuleReceiverSlow) {
  checkAgreement("bsdfvisualizer", kVisualizer, "barbule", kBarbuleReceiver, false);
}

namespace {

// Irradiance at `p` on the plane z = 0 (normal +z) from the disk light of ShearedDiskIrradiance,
// uniformly emitting radiance 1 downward: the midpoint rule in double precision over the unit
// disk's polar coordinates, mapped to the ellipse by the linear part A of its to_world.
double shearedDiskIrradiance(double px, double py) {
  // <scale x="0.5" y="0.3" z="1"/><rotate x="1" y="1" angle="180"/><translate z="1"/>: Rodrigues'
  // formula with the axis a = (1, 1, 0) as given and the angle pi is R = 2 a a^T - I, so
  // A = R diag(0.5, 0.3, 1) and the disk lies in the plane z = 1, facing -z.
  const double a[2][2] = {{0.5, 0.6}, {1.0, 0.3}};
  const double jacobian = std::abs(a[0][0] * a[1][1] - a[0][1] * a[1][0]);
  const int n = 1000;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double r = (i + 0.5) / n;
    for (int j = 0; j < n; ++j) {
      const double phi = 2.0 * M_PI * (j + 0.5) / n;
      const double lx = r * std::cos(phi), ly = r * std::sin(phi);
      const double dx = a[0][0] * lx + a[0][1] * ly - px, dy = a[1][0] * lx + a[1][1] * ly - py, dz = 1.0;
      const double d2 = dx * dx + dy * dy + dz * dz;
      // cos at the plane and at the light are both dz / d; dA = jacobian r dr dphi.
      sum += dz * dz / (d2 * d2) * jacobian * r;
    }
  }
  return sum * (1.0 / n) * (2.0 * M_PI / n);
}

std::string plateUnderShearedDisk(const char* integrator) {
  // A white diffuse plate seen through a 0.5 degree camera half a unit above (0.1, 0.05, 0):
  // each pixel is the plate's radiance there, E / pi.
  return std::string(R"(<scene version="3.0.0">)") + integrator +
         R"(<sensor type="perspective"><float name="fov" value="0.5"/>
      <transform name="to_world"><lookat origin="0.1, 0.05, 0.5" target="0.1, 0.05, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="4"/><integer name="height" value="4"/><rfilter type="box"/></film>
      <sampler type="independent"><integer name="sample_count" value="256"/></sampler></sensor>
    <shape type="rectangle"><transform name="to_world"><scale value="10"/></transform>
      <bsdf type="diffuse"><float name="reflectance" value="1"/></bsdf></shape>
    <shape type="disk"><transform name="to_world"><scale x="0.5" y="0.3" z="1"/><rotate x="1" y="1" angle="180"/>
        <translate z="1"/></transform>
      <emitter type="area"><spectrum name="radiance" value="1"/></emitter></shape></scene>)";
}

}  // namespace

TEST(EstimatorAgreement, ShearedDiskIrradianceMatchesQuadrature) {
  const double expected = shearedDiskIrradiance(0.1, 0.05) / M_PI;
  // White's luminance is 1 to the accuracy of the spectral tables and the wavelength sampling
  // (measured within 0.1 %, see test_transport.cpp).
  const double whiteTolerance = 0.002;
  for (const Estimator& estimator : {kEstimators[0], kEstimators[1], kEstimators[2]}) {
    const Estimate e = meanLuminanceOverSeeds(plateUnderShearedDisk(estimator.integrator), kSeeds, 70);
    EXPECT_NEAR(e.mean, expected, kSigmas * e.standardError + whiteTolerance * expected)
        << estimator.name << ": " << e.mean << " +- " << e.standardError << " against " << expected;
  }
}

namespace {
class EstimatorAgreementAtInfinity : public TempDirTest {};
}  // namespace

// An emitter at infinity under the to_world it accepts (a rotation with a mirror): a map bright
// in one corner of the sky, so that a direction mapped wrongly between sampling and lookup moves
// light; every estimator of a diffuse plate's image agrees.
TEST_F(EstimatorAgreementAtInfinity, EveryEstimatorAgreesUnderATurnedAndMirroredEnvmap) {
  Image sky(32, 16);
  for (int y = 0; y < sky.height; ++y)
    for (int x = 0; x < sky.width; ++x)
      for (int c = 0; c < 3; ++c) sky.rgb[3 * (size_t(y) * sky.width + x) + c] = (x < 8 && y < 6) ? 20.0f : 0.2f;
  const std::string map = (dir_ / "sky.exr").string();
  writeEXR(map, sky);
  std::vector<Estimate> estimates;
  for (const Estimator& estimator : kEstimators) {
    const std::string xml = std::string(R"(<scene version="3.0.0">)") + estimator.integrator + kPerspective +
                            R"(<shape type="rectangle"><transform name="to_world"><scale value="1.2"/></transform>)" +
                            kDiffuseReceiver + R"(</shape>
      <emitter type="envmap"><string name="filename" value=")" +
                            map + R"("/><transform name="to_world"><rotate x="0.6" y="0" z="0.8" angle="70"/>
        <scale x="-1"/></transform></emitter></scene>)";
    estimates.push_back(meanLuminanceOverSeeds(xml, kSeeds, 90));
  }
  for (size_t k = 0; k < estimates.size(); ++k)
    EXPECT_LT(standardErrorsApart(estimates[k], estimates[2]), kSigmas)
        << kEstimators[k].name << " " << estimates[k].mean << " +- " << estimates[k].standardError << " against "
        << estimates[2].mean << " +- " << estimates[2].standardError;
}

namespace {
// What building `xml` as a scene prints.
std::string sceneWarnings(const std::string& xml) {
  ::testing::internal::CaptureStderr();
  ParsedScene parsed = loadSceneString(xml, "scene.xml", ".", {}, builtinPlugins());
  Scene scene(parsed, SourceLocation{"scene.xml", 0});
  return ::testing::internal::GetCapturedStderr();
}

std::string receiverScene(const std::string& integrator, float exponent, bool throughInstance) {
  const std::string bsdf = R"(<bsdf type="twosided"><bsdf type="barbulebsdf"><float name="profile_exponent" value=")" +
                           std::to_string(exponent) + R"("/></bsdf></bsdf>)";
  const std::string receiver = throughInstance ? R"(<shape type="shapegroup" id="g"><shape type="rectangle">)" + bsdf +
                                                     R"(</shape></shape><shape type="instance"><ref id="g"/></shape>)"
                                               : R"(<shape type="rectangle">)" + bsdf + "</shape>";
  return R"(<scene version="3.0.0">)" + integrator + kPerspective + receiver +
         R"(<shape type="disk"><transform name="to_world"><translate z="1"/></transform>
              <emitter type="area"><spectrum name="radiance" value="1"/></emitter></shape></scene>)";
}
}  // namespace

TEST(EstimatorAgreement, AnIntegratorThatOnlyEvaluatesASingularBSDFIsWarnedOf) {
  for (const Estimator& estimator : kEstimators)
    for (bool instance : {false, true}) {
      const std::string warnings = sceneWarnings(receiverScene(estimator.integrator, 8.0f, instance));
      const bool warned = warnings.find("converges slowly and from below") != std::string::npos;
      EXPECT_EQ(warned, estimator.evaluatesOnly)
          << estimator.name << (instance ? ", through an instance" : "") << ": " << warnings;
      EXPECT_LE(std::count(warnings.begin(), warnings.end(), '\n'), 1) << warnings;
    }
  // At p 3 the square's integral diverges only logarithmically, and emitter sampling agreed with
  // MIS in the measurement of docs/model.md: no warning.
  EXPECT_EQ(sceneWarnings(receiverScene(kEstimators[0].integrator, 3.0f, false)), "");
}
