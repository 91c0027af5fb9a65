#include "optics/melanin.h"

#include <array>
#include <cstdint>
#include <iterator>

namespace columba {

namespace {

struct Sample {
  float lambda, reflectance;
};

// Intensity reflectance of the melanin layer under the barbule cortex, (wavelength nm,
// reflectance), from the measurements published with Huang et al. 2022 (melanin.r.spd).
constexpr Sample kMelanin[] = {
    {249.7909, 0.0300}, {253.6204, 0.0284}, {257.3179, 0.0267}, {260.5413, 0.0249}, {265.2469, 0.0234},
    {269.8353, 0.0217}, {275.3187, 0.0202}, {282.3302, 0.0199}, {288.3839, 0.0212}, {291.8836, 0.0232},
    {294.9088, 0.0249}, {297.6477, 0.0267}, {300.0853, 0.0284}, {302.9200, 0.0301}, {306.0012, 0.0319},
    {309.0825, 0.0335}, {312.3059, 0.0353}, {316.9616, 0.0368}, {320.8385, 0.0386}, {325.5842, 0.0402},
    {331.7368, 0.0412}, {338.6182, 0.0427}, {345.1091, 0.0438}, {352.2197, 0.0447}, {358.9984, 0.0454},
    {365.7771, 0.0458}, {372.5558, 0.0462}, {379.3345, 0.0464}, {386.1132, 0.0466}, {392.8919, 0.0469},
    {399.6706, 0.0470}, {406.4493, 0.0472}, {413.2280, 0.0476}, {420.0067, 0.0476}, {426.7854, 0.0477},
    {433.5641, 0.0479}, {440.3428, 0.0480}, {447.1215, 0.0482}, {453.9002, 0.0484}, {460.6789, 0.0487},
    {467.4576, 0.0490}, {474.2363, 0.0490}, {481.0150, 0.0490}, {487.7937, 0.0491}, {494.5724, 0.0495},
    {501.3511, 0.0496}, {508.1298, 0.0499}, {514.9085, 0.0503}, {521.6872, 0.0505}, {528.4659, 0.0508},
    {535.2446, 0.0510}, {542.0233, 0.0509}, {548.8020, 0.0510}, {555.5807, 0.0515}, {562.3594, 0.0516},
    {569.1381, 0.0517}, {575.9168, 0.0517}, {582.6955, 0.0518}, {589.4742, 0.0517}, {596.2529, 0.0519},
    {603.0316, 0.0522}, {609.8103, 0.0523}, {616.5890, 0.0526}, {623.3677, 0.0529}, {630.1464, 0.0534},
    {636.9251, 0.0538}, {643.7038, 0.0542}, {650.4825, 0.0544}, {657.2612, 0.0547}, {664.0399, 0.0548},
    {670.7238, 0.0551}, {677.5973, 0.0555}, {684.3760, 0.0556}, {691.1547, 0.0559}, {697.9334, 0.0562},
    {704.7121, 0.0562}, {711.4908, 0.0565}, {718.2695, 0.0568}, {725.0482, 0.0569}, {731.8269, 0.0569},
    {738.6056, 0.0573}, {745.3843, 0.0575}, {752.1630, 0.0575}, {758.9417, 0.0577}, {765.7204, 0.0578},
    {772.4991, 0.0581}, {779.2778, 0.0581}, {786.0565, 0.0582}, {792.8352, 0.0583}, {799.6139, 0.0584},
    {806.3926, 0.0587}, {813.1713, 0.0587}, {819.9500, 0.0589}, {826.7287, 0.0589}, {833.5074, 0.0591},
    {840.2861, 0.0593}, {847.0648, 0.0594}, {853.8435, 0.0593}, {860.6222, 0.0593}, {867.4009, 0.0594},
    {874.1796, 0.0594}, {880.9584, 0.0594}, {887.7371, 0.0594}, {894.5158, 0.0595}, {900.0620, 0.0593},
};

constexpr int kSamples = int(std::size(kMelanin));
constexpr int kCells = int(kMelanin[kSamples - 1].lambda - kMelanin[0].lambda) + 1;

// The segment [kMelanin[i], kMelanin[i + 1]] holding the start of each whole-nanometre cell from the
// first sample on. Samples lie more than 1 nm apart, so a lookup is one table read and at most one
// step forward, not a search.
constexpr std::array<uint8_t, kCells> segmentTable() {
  std::array<uint8_t, kCells> table{};
  int segment = 0;
  for (int cell = 0; cell < kCells; ++cell) {
    float start = kMelanin[0].lambda + float(cell);
    while (segment + 2 < kSamples && kMelanin[segment + 1].lambda <= start) ++segment;
    table[cell] = uint8_t(segment);
  }
  return table;
}
constexpr std::array<uint8_t, kCells> kSegmentOfCell = segmentTable();

// Each segment's slope, so that a lookup needs no division.
constexpr std::array<float, kSamples - 1> slopeTable() {
  std::array<float, kSamples - 1> slopes{};
  for (int i = 0; i + 1 < kSamples; ++i)
    slopes[i] = (kMelanin[i + 1].reflectance - kMelanin[i].reflectance) / (kMelanin[i + 1].lambda - kMelanin[i].lambda);
  return slopes;
}
constexpr std::array<float, kSamples - 1> kSlope = slopeTable();

}  // namespace

float melaninReflectance(float lambdaNm) {
  if (!(lambdaNm > kMelanin[0].lambda)) return kMelanin[0].reflectance;
  if (lambdaNm >= kMelanin[kSamples - 1].lambda) return kMelanin[kSamples - 1].reflectance;
  int segment = kSegmentOfCell[int(lambdaNm - kMelanin[0].lambda)];
  segment += lambdaNm >= kMelanin[segment + 1].lambda;  // without a branch: it goes either way
  return kMelanin[segment].reflectance + (lambdaNm - kMelanin[segment].lambda) * kSlope[segment];
}

}  // namespace columba
