#include <gtest/gtest.h>

#include "bsdfs/conductor.h"
#include "bsdfs/roughconductor.h"
#include "optics/conductor_fresnel.h"
#include "optics/conductor_materials.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {
const BSDFContext kContext;

// Normal-incidence reflectance of a metal of complex index n + ik: ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2).
double normalReflectance(double n, double k) { return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k); }

std::shared_ptr<BSDF> conductorOf(const std::string& material) {
  Properties props;
  setString(props, "material", material);
  return std::dynamic_pointer_cast<BSDF>(makeConductorBSDF(props));
}
}  // namespace

TEST(ConductorMaterials, TablesHoldThePublishedValues) {
  // Rows of the published tables, at their own wavelengths (Johnson & Christy 1972 and 1974, Rakic
  // 1995), and a value halfway between two rows.
  struct Row {
    const char* name;
    float lambda, n, k;
  };
  for (const Row& r :
       {Row{"Au", 659.5f, 0.14f, 3.697f}, Row{"Ag", 548.6f, 0.06f, 3.586f}, Row{"Cu", 450.9f, 1.24f, 2.397f},
        Row{"Cr", 549.0f, 3.18f, 3.33f}, Row{"Al", 516.6f, 0.8734f, 6.2418f}}) {
    std::optional<ConductorIndex> index = conductorIndex(r.name);
    ASSERT_TRUE(index) << r.name;
    EXPECT_NEAR(index->eta.eval(r.lambda), r.n, 1e-5f) << r.name;
    EXPECT_NEAR(index->k.eval(r.lambda), r.k, 1e-5f) << r.name;
  }
  EXPECT_NEAR(conductorIndex("Au")->eta.eval(0.5f * (548.6f + 582.1f)), 0.5f * (0.43f + 0.29f), 1e-5f);
  EXPECT_FALSE(conductorIndex("Unobtainium"));
  EXPECT_EQ(conductorNames().rfind("Ag, Al, AlAs, AlAs_palik, AlSb", 0), 0u) << conductorNames();
}

// Mitsuba's other named conductors, compiled in from data/ior/: rows of the tables as the files
// give them (tungsten's first row, amorphous carbon's first k row), and every name Mitsuba 3's
// conductor documents.
TEST(ConductorMaterials, MitsubasNamedConductorsAreKnown) {
  EXPECT_NEAR(conductorIndex("W")->eta.eval(302.389984f), 2.97f, 1e-5f);
  EXPECT_NEAR(conductorIndex("W")->k.eval(302.389984f), 2.37f, 1e-5f);
  EXPECT_NEAR(conductorIndex("a-C")->k.eval(309.950012f), 0.808f, 1e-5f);
  for (const char* name :
       {"a-C",       "AlAs",      "AlAs_palik", "AlSb",       "AlSb_palik", "Be",         "Be_palik", "CsI",
        "CsI_palik", "Cu_palik",  "Cu2O",       "Cu2O_palik", "CuO",        "CuO_palik",  "d-C",      "d-C_palik",
        "Hg",        "Hg_palik",  "HgTe",       "HgTe_palik", "Ir",         "Ir_palik",   "K",        "K_palik",
        "Li",        "Li_palik",  "MgO",        "MgO_palik",  "Na_palik",   "Nb",         "Nb_palik", "Ni_palik",
        "Rh",        "Rh_palik",  "Se",         "Se_palik",   "SiC",        "SiC_palik",  "SnTe",     "SnTe_palik",
        "Ta",        "Ta_palik",  "Te",         "Te_palik",   "ThF4",       "ThF4_palik", "TiC",      "TiC_palik",
        "TiN",       "TiN_palik", "TiO2",       "TiO2_palik", "VC",         "VC_palik",   "V_palik",  "VN",
        "VN_palik",  "W"}) {
    const std::optional<ConductorIndex> index = conductorIndex(name);
    ASSERT_TRUE(index) << name;
    EXPECT_GT(index->eta.eval(550.0f), 0.0f) << name;
    EXPECT_GE(index->k.eval(550.0f), 0.0f) << name;
  }
}

TEST(ConductorBSDF, MirrorsWithTheMetalsFresnelReflectance) {
  // Gold at normal incidence: its sample's weight is ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2) at each
  // of the path's wavelengths, computed here from the table's values.
  auto gold = conductorOf("Au");
  ASSERT_TRUE(gold);
  Wavelengths wl = Wavelengths::fixed({450.9f, 548.6f, 659.5f, 756.0f});
  const double n[] = {1.38, 0.43, 0.14, 0.14}, k[] = {1.914, 2.455, 3.697, 4.542};
  auto s = gold->sample(kContext, Vec3(0, 0, 1), wl, 0.5f, Vec2(0.5f, 0.5f));
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->delta);
  EXPECT_EQ(s->wo.z, 1.0f);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(s->weight[i], normalReflectance(n[i], k[i]), 1e-4) << wl[i];
  // Gold reflects red far more than blue.
  EXPECT_GT(s->weight[2], s->weight[0] + 0.5f);
  // Oblique: the mirror direction; nothing from below.
  Vec3 wi = directionAt(60.0f, 30.0f);
  auto oblique = gold->sample(kContext, wi, wl, 0.5f, Vec2(0.5f, 0.5f));
  ASSERT_TRUE(oblique);
  EXPECT_NEAR(oblique->wo.x, -wi.x, 1e-7f);
  EXPECT_NEAR(oblique->wo.z, wi.z, 1e-7f);
  EXPECT_FALSE(gold->sample(kContext, Vec3(0, 0, -1), wl, 0.5f, Vec2(0.5f, 0.5f)));
  // No material: a perfect mirror.
  EXPECT_EQ(conductorOf("none")->sample(kContext, wi, wl, 0.5f, Vec2(0.5f, 0.5f))->weight[1], 1.0f);
}

TEST(ConductorBSDF, MaterialNamesAreCheckedForBothConductors) {
  EXPECT_THROW(conductorOf("Unobtainium"), InputError);
  try {
    conductorOf("Pt");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("known: none, Ag, Al, AlAs"), std::string::npos) << e.what();
  }
  Properties both;
  setString(both, "material", "Cu");
  setFloat(both, "eta", 0.2f);
  EXPECT_THROW(makeConductorBSDF(both), InputError);
  // roughconductor reads the same names: copper at normal incidence (alpha tiny) reflects the table's value.
  Properties rough;
  setString(rough, "material", "Cu");
  setFloat(rough, "alpha", 0.001f);
  auto copper = std::dynamic_pointer_cast<BSDF>(makeRoughConductorBSDF(rough));
  ASSERT_TRUE(copper);
  Wavelengths wl = Wavelengths::fixed({450.9f, 548.6f, 659.5f, 756.0f});
  auto s = copper->sample(kContext, Vec3(0, 0, 1), wl, 0.5f, Vec2(0.3f, 0.6f));
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->weight[0], normalReflectance(1.24, 2.397), 2e-3);
  EXPECT_NEAR(s->weight[2], normalReflectance(0.22, 3.747), 2e-3);
}

// A negative eta or k is no passive medium: eta -1, k 0 rendered pixels of 6e14, eta -5, k -5 an
// albedo above 1.
TEST(ConductorBSDF, NegativeOpticalConstantsAreRefusedNamingTheLine) {
  for (const char* type : {"conductor", "roughconductor"}) {
    for (const char* parameters : {R"(<float name="eta" value="-1"/><float name="k" value="0"/>)",
                                   R"(<float name="eta" value="-5"/><float name="k" value="-5"/>)",
                                   R"(<float name="eta" value="1.5"/><spectrum name="k" value="400:2, 700:-0.5"/>)",
                                   R"(<rgb name="eta" value="0.2, -0.1, 0.3"/><float name="k" value="3"/>)"}) {
      const std::string message = loadBSDFError(type, parameters);
      EXPECT_NE(message.find(std::string(type) + ".xml:3"), std::string::npos) << message;
      EXPECT_NE(message.find("cannot be negative"), std::string::npos) << message;
    }
  }
}

// eta = k = 0 (a black texel of both textures) divided by zero: the limit, total reflection.
TEST(ConductorBSDF, AVanishingIndexReflectsEverything) {
  for (float cosI : {1.0f, 0.5f, 0.01f}) EXPECT_EQ(fresnelConductor(cosI, 0.0f, 0.0f), 1.0f) << cosI;
  const Wavelengths wl = Wavelengths::fixed({450.0f, 550.0f, 650.0f, 750.0f});
  auto mirror = loadBSDF("conductor", R"(<float name="eta" value="0"/><float name="k" value="0"/>)");
  auto s = mirror->sample(kContext, normalize(Vec3(0.3f, 0.0f, 1.0f)), wl, 0.5f, Vec2(0.5f, 0.5f));
  ASSERT_TRUE(s);
  EXPECT_EQ(s->weight[0], 1.0f);
}
