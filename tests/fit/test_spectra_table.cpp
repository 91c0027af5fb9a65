// Spectra tables as biologists keep them: the long layout, pavo's wide layout, a two-column
// spectrum and columba bsdf's specular table, with the geometry given or read from the columns.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "core/error.h"
#include "fit/fit_parameter.h"
#include "fit/spectra_fit.h"
#include "fit/spectra_table.h"
#include "support/temp_dir_test.h"

using namespace columba;
using columba::testing::TempDirTest;

class SpectraTable : public TempDirTest {};

TEST_F(SpectraTable, ATwoColumnSpectrumTakesTheGeometryGiven) {
  const std::string path = write("msp.csv", "# a microspectrophotometer's spectrum\nwl,R\n450,0.1\n500,0.3\n550,0.2\n");
  SpectraGeometry mirror;
  mirror.thetaI = {30.0f};
  mirror.phiI = 10.0f;
  std::vector<SpectraSample> s = readSpectraCSV(path, mirror);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[1].wavelength, 500.0f);
  EXPECT_EQ(s[1].reflectance, 0.3f);
  EXPECT_EQ(s[1].thetaI, 30.0f);
  EXPECT_EQ(s[1].thetaO, 30.0f);
  EXPECT_EQ(s[1].phiO, 190.0f);  // the mirror direction
  SpectraGeometry normal = mirror;
  normal.view = SpectraGeometry::View::Normal;
  EXPECT_EQ(readSpectraCSV(path, normal)[0].thetaO, 0.0f);
  // Without a geometry the spectrum is refused, naming its column.
  try {
    readSpectraCSV(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("msp.csv:2: column 'R' is a spectrum without directions"), std::string::npos)
        << e.what();
  }
}

TEST_F(SpectraTable, PavosWideLayoutGivesOneSpectrumPerColumn) {
  const std::string path = write("pavo.csv", "wl,green,purple\n400,0.1,0.5\n500,0.6,0.2\n600,0.2,0.4\n");
  SpectraGeometry g;
  g.thetaI = {10.0f, 40.0f};
  std::vector<SpectraSample> s = readSpectraCSV(path, g);
  ASSERT_EQ(s.size(), 6u);
  // Each spectrum's wavelengths together, in column order.
  EXPECT_EQ(s[0].thetaI, 10.0f);
  EXPECT_EQ(s[2].thetaI, 10.0f);
  EXPECT_EQ(s[2].reflectance, 0.2f);
  EXPECT_EQ(s[3].thetaI, 40.0f);
  EXPECT_EQ(s[4].reflectance, 0.2f);
  g.thetaI = {10.0f, 20.0f, 30.0f};
  EXPECT_THROW(readSpectraCSV(path, g), InputError);  // three angles for two spectra
}

TEST_F(SpectraTable, ColumbaBsdfsSpecularTableIsReadAsIs) {
  const std::string path =
      write("bsdf_specular.csv",
            "# reflectance factor pi f(light, mirror direction)\n# b 0.25 | height 0.6 um\n"
            "wavelength_nm,R_theta10,TRT_theta10,total_theta10,R_theta30,TRT_theta30,total_theta30\n"
            "450,0.2,0.05,0.25,0.1,0.04,0.14\n550,0.3,0.05,0.35,0.2,0.04,0.24\n");
  std::vector<SpectraSample> s = readSpectraCSV(path);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].thetaI, 10.0f);
  EXPECT_EQ(s[0].phiO, 180.0f);
  EXPECT_EQ(s[1].reflectance, 0.35f);
  EXPECT_EQ(s[2].thetaI, 30.0f);
  EXPECT_EQ(s[3].reflectance, 0.24f);
}

TEST_F(SpectraTable, AFitOfATwoColumnSpectrumRecoversTheModelsThickness) {
  // A 30-degree mirror spectrum made by the model at 0.58 um, written as a two-column file.
  std::vector<SpectraSample> model;
  for (float lambda = 400.0f; lambda <= 700.0f; lambda += 5.0f) model.push_back({30, 0, 30, 180, lambda, 0});
  const std::vector<float> values = modelSpectra(barbuleParametersWith({{"height", 0.58}}), model);
  std::string text = "wavelength,reflectance\n";
  for (size_t i = 0; i < model.size(); ++i) text += fmt::format("{},{}\n", model[i].wavelength, values[i]);
  SpectraGeometry g;
  g.thetaI = {30.0f};
  SpectraFitSettings settings;
  settings.samples = readSpectraCSV(write("model.csv", text), g);
  settings.parameters = {parseFitParameter("height=0.5:0.7")};
  EXPECT_NEAR(fitSpectra(settings).fit.values[0], 0.58, 0.002);
}

TEST_F(SpectraTable, ARetroDirectionInTheLongLayoutIsWarnedAbout) {
  // phi_o = phi_i puts omega_o on the light's side: not where a specular spectrum is measured.
  const std::string path = write(
      "retro.csv", "theta_i,phi_i,theta_o,phi_o,wavelength_nm,reflectance\n30,0,30,0,500,0.2\n30,0,30,0,510,0.2\n");
  ::testing::internal::CaptureStderr();
  std::vector<SpectraSample> s = readSpectraCSV(path);
  const std::string warnings = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(s.size(), 2u);
  EXPECT_NE(warnings.find("retro.csv:2: phi_o equals phi_i"), std::string::npos) << warnings;
  EXPECT_EQ(warnings.find("retro.csv:3"), std::string::npos) << "warned once: " << warnings;
}

TEST_F(SpectraTable, SpectraFromTheUltravioletAreReadAndShorterOnesRefused) {
  // Biologists measure from 300 nm, where birds' cones begin; below it is an error naming the line.
  SpectraGeometry mirror;
  mirror.thetaI = {20.0f};
  const std::vector<SpectraSample> s = readSpectraCSV(write("uv.csv", "wl,R\n300,0.05\n350,0.1\n700,0.2\n"), mirror);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].wavelength, 300.0f);
  try {
    readSpectraCSV(write("deep.csv", "wl,R\n299,0.05\n350,0.1\n"), mirror);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("deep.csv:2: wavelength_nm 299 lies outside 300..830 nm"), std::string::npos)
        << e.what();
  }
}

TEST_F(SpectraTable, AFitThatScalesTheModelFarFrom1IsWarnedAbout) {
  // Spectra in percent fit with a scale near 100; a retro spectrum fits (0.548 um for 0.58) only with
  // a scale of about 5: both are named. Within a factor of 3 nothing is said.
  EXPECT_FALSE(implausibleScaleWarning(1.0));
  EXPECT_FALSE(implausibleScaleWarning(2.5));
  EXPECT_NE(implausibleScaleWarning(97.0).value_or("").find("100 times larger"), std::string::npos);
  EXPECT_NE(implausibleScaleWarning(0.011).value_or("").find("100 times smaller"), std::string::npos);
  EXPECT_NE(implausibleScaleWarning(4.84).value_or("").find("phi_o = phi_i + 180"), std::string::npos);
  // A model-made spectrum written in percent: the fit recovers the thickness, at a scale of 100.
  std::vector<SpectraSample> model;
  for (float lambda = 400.0f; lambda <= 700.0f; lambda += 5.0f) model.push_back({30, 0, 30, 180, lambda, 0});
  const std::vector<float> values = modelSpectra(barbuleParametersWith({{"height", 0.58}}), model);
  std::string text = "wl,R\n";
  for (size_t i = 0; i < model.size(); ++i) text += fmt::format("{},{}\n", model[i].wavelength, 100.0f * values[i]);
  SpectraGeometry g;
  g.thetaI = {30.0f};
  SpectraFitSettings settings;
  settings.samples = readSpectraCSV(write("percent.csv", text), g);
  settings.parameters = {parseFitParameter("height=0.5:0.7")};
  const FitResult r = fitSpectra(settings).fit;
  EXPECT_NEAR(r.values[0], 0.58, 0.002);
  EXPECT_NEAR(r.loss.scale, 100.0, 1.0);
  EXPECT_TRUE(implausibleScaleWarning(r.loss.scale));
}
