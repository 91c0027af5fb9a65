// Observers read from tables of sensitivities: the blue tit's own curves read back as the built-in
// observer, a coarse table interpolated and normalised, bad tables refused naming the line, and a
// render with a table's observer catching what the built-in one catches.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "support/error_test_support.h"
#include "support/render_test_support.h"
#include "support/temp_dir_test.h"
#include "vision/observer_table.h"

using namespace columba;
using columba::testing::TempDirTest;

namespace {
// The blue tit's curves as a table, every `step` nm from 300 to 830 nm; where `largest` is given,
// scaled so that the largest value is `largest`.
std::string blueTitTable(int step, double largest = 0.0) {
  const Observer o = namedObserver("bluetit");
  float peak = 0.0f;
  for (const std::vector<float>& s : o.sensitivities) peak = std::max(peak, *std::max_element(s.begin(), s.end()));
  auto value = [&](size_t c, size_t i) {
    return largest > 0.0 ? o.sensitivities[c][i] / peak * largest : o.sensitivities[c][i];
  };
  std::string text = "# the blue tit, written from Columba's own curves\nwl,UVS,SWS,MWS,LWS\n";
  for (size_t i = 0; i < o.grid.count; i += size_t(step))
    text += fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g}\n", o.grid.wavelength(i), value(0, i), value(1, i), value(2, i),
                        value(3, i));
  return text;
}

std::string tableError(const std::string& text) {
  std::istringstream in(text);
  try {
    readObserverTable(in, "eye.csv", "eye");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A 4 x 4 render of a lit diffuse plane by a film with `observer`.
Image renderWithObserver(const std::string& observer) {
  return columba::testing::renderSceneString(R"(<scene version="3.0.0"><integrator type="direct"/>
      <sensor type="perspective"><float name="fov" value="1"/>
        <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="4"/><integer name="height" value="4"/>
          <string name="observer" value=")" + observer +
                                             R"("/></film>
        <sampler type="ldsampler"><integer name="sample_count" value="64"/></sampler></sensor>
      <shape type="rectangle"><transform name="to_world"><scale value="10"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.2, 0.5, 0.3"/></bsdf></shape>
      <emitter type="directional"><vector name="direction" x="0" y="0" z="-1"/>
        <float name="irradiance" value="3"/></emitter></scene>)");
}
}  // namespace

TEST(ObserverTable, ABuiltInObserversOwnCurvesReadBackAsIt) {
  std::istringstream in(blueTitTable(1));
  const Observer table = readObserverTable(in, "bluetit.csv", "bluetit-table");
  const Observer builtIn = namedObserver("bluetit");
  EXPECT_EQ(table.name, "bluetit-table");
  EXPECT_EQ(table.channels, builtIn.channels);
  for (size_t c = 0; c < 4; ++c)
    for (size_t i = 0; i < table.grid.count; ++i)
      ASSERT_NEAR(table.sensitivities[c][i], builtIn.sensitivities[c][i], 1e-6) << c << " " << i;
  EXPECT_EQ(table.noise.relativeDensities, (std::vector<double>{1, 2, 2, 4}));  // pavo's coldist default
  EXPECT_EQ(table.noise.weberReference, 3u);
  EXPECT_EQ(table.noise.weberFraction, 0.1);
  EXPECT_FALSE(table.hasAchromatic());
}

TEST(ObserverTable, ACoarseTableIsInterpolatedAndHasAreaOne) {
  // Triangles on a 10 nm grid: linear between rows, zero outside the table (400-600 nm), area 1.
  std::istringstream in("wavelength_nm\tVS\tLWS\tDBL\n400 0 0 1\n450 2 1 1\n500 0 2 1\n600 0 0 1\n");
  const Observer o = readObserverTable(in, "eye.csv", "eye");
  ASSERT_EQ(o.channels, (std::vector<std::string>{"VS", "LWS"}));
  ASSERT_TRUE(o.hasAchromatic());
  EXPECT_EQ(o.noise.relativeDensities, (std::vector<double>{1, 4}));
  auto at = [&](const std::vector<float>& s, double nm) { return s[size_t(nm - o.grid.firstNm)]; };
  // VS: a triangle of height 2 and base 100 nm, area 100; so 0.02 at its peak, 0.01 half way.
  EXPECT_NEAR(at(o.sensitivities[0], 450), 0.02, 1e-6);
  EXPECT_NEAR(at(o.sensitivities[0], 425), 0.01, 1e-6);
  EXPECT_EQ(at(o.sensitivities[0], 399), 0.0f);
  EXPECT_EQ(at(o.achromatic, 601), 0.0f);
  EXPECT_NEAR(at(o.achromatic, 500), 1.0 / 201.0, 1e-6);  // flat over 400-600 nm on the 1 nm grid
  for (const std::vector<float>& s : {o.sensitivities[0], o.sensitivities[1], o.achromatic})
    EXPECT_NEAR(integrateOnGrid(o.grid, s), 1.0, 1e-5);
}

// Sensitivities are in any unit: a curve whose largest value is 1e308 once summed to an infinite
// area, every catch of that cone to NaN; tiny ones keep their precision.
TEST(ObserverTable, ATableInAnyUnitGivesTheSameObserver) {
  std::istringstream unit(blueTitTable(5));
  const Observer one = readObserverTable(unit, "unit.csv", "unit");
  for (double largest : {1e308, 1e-300}) {
    std::istringstream in(blueTitTable(5, largest));
    const Observer scaled = readObserverTable(in, "scaled.csv", "scaled");
    for (size_t c = 0; c < 4; ++c)
      for (size_t i = 0; i < one.grid.count; ++i)
        ASSERT_NEAR(scaled.sensitivities[c][i], one.sensitivities[c][i], 1e-6 * one.sensitivities[c][i] + 1e-12)
            << largest << " " << c << " " << i;
  }
}

TEST(ObserverTable, BadTablesAreRefusedNamingTheLine) {
  using columba::testing::expectContains;
  expectContains(tableError("nm,UVS,SWS\n"), {"eye.csv:1", "not a wavelength column"});
  expectContains(tableError("wl,UVS,green\n"), {"eye.csv:1", "'green' is not a cone"});
  expectContains(tableError("wl,SWS,SWS\n"), {"eye.csv:1", "'SWS' is given twice"});
  expectContains(tableError("wl,UVS,SWS\n300,0.1,0.2\n310,x,0.2\n"), {"eye.csv:3", "'x' is not a number"});
  expectContains(tableError("wl,UVS,SWS\n300,0.1,0.2\n300,0.1,0.2\n"), {"eye.csv:3", "must increase"});
  expectContains(tableError("wl,UVS,SWS\n300,0.1,0.2\n310,0.1\n"), {"eye.csv:3", "a row of 2 values"});
  expectContains(tableError("wl,UVS,SWS\n300,-0.1,0.2\n310,0.1,0.2\n"), {"eye.csv:2", "not negative"});
  expectContains(tableError("wl,UVS,VS,SWS\n300,1,1,1\n310,1,1,1\n"), {"eye.csv:1", "UVS or a VS cone, not both"});
  expectContains(tableError("wl,LWS,DBL\n300,1,1\n310,1,1\n"), {"eye.csv:1", "fewer than two chromatic cones"});
  expectContains(tableError("wl,UVS,SWS\n900,1,1\n910,1,1\n"), {"eye.csv:1", "no sensitivity between 300 and 830"});
  expectContains(tableError("# nothing\n"), {"eye.csv:1", "no header row"});
}

class ObserverTableFile : public TempDirTest {};

// As spreadsheet programs save text: line 1 was "the first column is '<BOM>wl', not a wavelength
// column", and a definition's header was taken for a table's.
TEST_F(ObserverTableFile, ATableOrDefinitionMayStartWithAByteOrderMark) {
  const Observer marked = readObserverTableFile(write("marked.csv", "\xEF\xBB\xBF" + blueTitTable(5)));
  const Observer plain = readObserverTableFile(write("plain.csv", blueTitTable(5)));
  ASSERT_EQ(marked.channels, plain.channels);
  EXPECT_EQ(marked.sensitivities, plain.sensitivities);
  const Observer defined = readObserverTableFile(write("defined.csv",
                                                       "\xEF\xBB\xBF"
                                                       "cone, lambda_max, droplet\nSWS, 450, NA\nLWS, 560, NA\n"));
  EXPECT_EQ(defined.channels, (std::vector<std::string>{"SWS", "LWS"}));
}

TEST_F(ObserverTableFile, ARenderWithATablesObserverCatchesWhatTheBuiltInOneDoes) {
  const std::string table = write("bluetit.csv", blueTitTable(1));
  const Image fromTable = renderWithObserver(table), builtIn = renderWithObserver("bluetit");
  ASSERT_EQ(fromTable.cones.names, builtIn.cones.names);
  for (size_t i = 0; i < builtIn.cones.values.size(); ++i)
    EXPECT_NEAR(fromTable.cones.values[i], builtIn.cones.values[i], 1e-4 * builtIn.cones.values[i]) << i;
  // A table whose largest value is 1e308 catches the same (its channels were NaN in every pixel).
  const Image huge = renderWithObserver(write("huge.csv", blueTitTable(1, 1e308)));
  ASSERT_EQ(huge.cones.names, builtIn.cones.names);
  for (size_t i = 0; i < builtIn.cones.values.size(); ++i)
    EXPECT_NEAR(huge.cones.values[i], builtIn.cones.values[i], 1e-4 * builtIn.cones.values[i]) << i;
  // A table that is not there is named with where it was looked for.
  try {
    renderWithObserver("nowhere.csv");
    FAIL() << "no error";
  } catch (const InputError& e) {
    columba::testing::expectContains(e.what(), {"observer", "nowhere.csv", "not found"});
  }
}
