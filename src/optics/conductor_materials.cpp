#include "optics/conductor_materials.h"

#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "optics/conductor_tables.h"

namespace columba {

namespace {

struct NK {
  float lambda, n, k;  // nm, real and imaginary parts of the index
};

// Au: P. B. Johnson and R. W. Christy, "Optical constants of the noble metals", Phys. Rev. B 6, 4370 (1972).
constexpr NK kAu[] = {
    {300.9f, 1.53f, 1.889f}, {310.7f, 1.53f, 1.893f}, {320.4f, 1.54f, 1.898f}, {331.5f, 1.48f, 1.883f},
    {342.5f, 1.48f, 1.871f}, {354.2f, 1.5f, 1.866f},  {367.9f, 1.48f, 1.895f}, {381.5f, 1.46f, 1.933f},
    {397.4f, 1.47f, 1.952f}, {413.3f, 1.46f, 1.958f}, {430.5f, 1.45f, 1.948f}, {450.9f, 1.38f, 1.914f},
    {471.4f, 1.31f, 1.849f}, {495.9f, 1.04f, 1.833f}, {520.9f, 0.62f, 2.081f}, {548.6f, 0.43f, 2.455f},
    {582.1f, 0.29f, 2.863f}, {616.8f, 0.21f, 3.272f}, {659.5f, 0.14f, 3.697f}, {704.5f, 0.13f, 4.103f},
    {756.0f, 0.14f, 4.542f}, {821.1f, 0.16f, 5.083f}, {892.0f, 0.17f, 5.663f}, {984.0f, 0.22f, 6.35f},
};
// Ag: P. B. Johnson and R. W. Christy, "Optical constants of the noble metals", Phys. Rev. B 6, 4370 (1972).
constexpr NK kAg[] = {
    {300.9f, 1.34f, 0.964f}, {310.7f, 1.13f, 0.616f}, {320.4f, 0.81f, 0.392f}, {331.5f, 0.17f, 0.829f},
    {342.5f, 0.14f, 1.142f}, {354.2f, 0.1f, 1.419f},  {367.9f, 0.07f, 1.657f}, {381.5f, 0.05f, 1.864f},
    {397.4f, 0.05f, 2.07f},  {413.3f, 0.05f, 2.275f}, {430.5f, 0.04f, 2.462f}, {450.9f, 0.04f, 2.657f},
    {471.4f, 0.05f, 2.869f}, {495.9f, 0.05f, 3.093f}, {520.9f, 0.05f, 3.324f}, {548.6f, 0.06f, 3.586f},
    {582.1f, 0.05f, 3.858f}, {616.8f, 0.06f, 4.152f}, {659.5f, 0.05f, 4.483f}, {704.5f, 0.04f, 4.838f},
    {756.0f, 0.03f, 5.242f}, {821.1f, 0.04f, 5.727f}, {892.0f, 0.04f, 6.312f}, {984.0f, 0.04f, 6.992f},
};
// Cu: P. B. Johnson and R. W. Christy, "Optical constants of the noble metals", Phys. Rev. B 6, 4370 (1972).
constexpr NK kCu[] = {
    {300.9f, 1.4f, 1.679f},  {310.7f, 1.38f, 1.729f}, {320.4f, 1.38f, 1.783f}, {331.5f, 1.34f, 1.821f},
    {342.5f, 1.36f, 1.864f}, {354.2f, 1.37f, 1.916f}, {367.9f, 1.36f, 1.975f}, {381.5f, 1.33f, 2.045f},
    {397.4f, 1.32f, 2.116f}, {413.3f, 1.28f, 2.207f}, {430.5f, 1.25f, 2.305f}, {450.9f, 1.24f, 2.397f},
    {471.4f, 1.25f, 2.483f}, {495.9f, 1.22f, 2.564f}, {520.9f, 1.18f, 2.608f}, {548.6f, 1.02f, 2.577f},
    {582.1f, 0.7f, 2.704f},  {616.8f, 0.3f, 3.205f},  {659.5f, 0.22f, 3.747f}, {704.5f, 0.21f, 4.205f},
    {756.0f, 0.24f, 4.665f}, {821.1f, 0.26f, 5.18f},  {892.0f, 0.3f, 5.768f},  {984.0f, 0.32f, 6.421f},
};
// Cr: P. B. Johnson and R. W. Christy, "Optical constants of transition metals", Phys. Rev. B 9, 5056 (1974).
constexpr NK kCr[] = {
    {301.0f, 1.53f, 2.34f}, {311.0f, 1.58f, 2.4f},  {320.0f, 1.65f, 2.47f}, {332.0f, 1.69f, 2.53f},
    {342.0f, 1.76f, 2.58f}, {354.0f, 1.84f, 2.64f}, {368.0f, 1.87f, 2.69f}, {381.0f, 1.92f, 2.74f},
    {397.0f, 2.0f, 2.83f},  {413.0f, 2.08f, 2.93f}, {431.0f, 2.19f, 3.04f}, {451.0f, 2.33f, 3.14f},
    {471.0f, 2.51f, 3.24f}, {496.0f, 2.75f, 3.3f},  {521.0f, 2.94f, 3.33f}, {549.0f, 3.18f, 3.33f},
    {582.0f, 3.22f, 3.3f},  {617.0f, 3.17f, 3.3f},  {659.0f, 3.09f, 3.34f}, {704.0f, 3.05f, 3.39f},
    {756.0f, 3.08f, 3.42f}, {821.0f, 3.2f, 3.48f},  {892.0f, 3.3f, 3.52f},  {984.0f, 3.41f, 3.57f},
};
// Al: A. D. Rakic, "Algorithm for the determination of intrinsic optical constants of metal films: application to
// aluminum", Appl. Opt. 34, 4755 (1995).
constexpr NK kAl[] = {
    {309.96f, 0.28003f, 3.7081f}, {326.28f, 0.31474f, 3.9165f}, {364.66f, 0.39877f, 4.3957f},
    {413.28f, 0.52135f, 5.0008f}, {442.8f, 0.6079f, 5.3676f},   {476.87f, 0.7278f, 5.7781f},
    {516.6f, 0.8734f, 6.2418f},   {563.57f, 1.0728f, 6.7839f},  {619.93f, 1.366f, 7.4052f},
    {652.25f, 1.5724f, 7.7354f},  {688.81f, 1.8301f, 8.0601f},  {729.32f, 2.1606f, 8.3565f},
    {774.91f, 2.6154f, 8.4914f},  {794.78f, 2.7675f, 8.3866f},  {815.69f, 2.7668f, 8.2573f},
    {837.74f, 2.6945f, 8.1878f},  {885.61f, 2.2802f, 8.1134f},  {911.66f, 1.9739f, 8.3058f},
    {939.28f, 1.6784f, 8.597f},   {968.63f, 1.4867f, 9.0655f},  {999.88f, 1.4359f, 9.4939f},
};

template <size_t N>
ConductorIndex indexOf(const NK (&table)[N]) {
  std::vector<float> lambdas, n, k;
  for (const NK& row : table) {
    lambdas.push_back(row.lambda);
    n.push_back(row.n);
    k.push_back(row.k);
  }
  return {SpectralDistribution::piecewiseLinear(lambdas, n), SpectralDistribution::piecewiseLinear(lambdas, k)};
}

// A compiled-in .spd table: '#' lines are comments, the others a wavelength (nm) and a value.
SpectralDistribution spdTable(const char* name, const char* text) {
  std::vector<float> lambdas, values;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    float lambda = 0.0f, value = 0.0f;
    // The tables are part of the build; a malformed one is a packaging error.
    if (!(row >> lambda >> value)) throw std::logic_error(std::string("malformed optical constants of ") + name);
    lambdas.push_back(lambda);
    values.push_back(value);
  }
  return SpectralDistribution::piecewiseLinear(lambdas, values);
}

const std::map<std::string, ConductorIndex>& materials() {
  static const std::map<std::string, ConductorIndex> table = [] {
    std::map<std::string, ConductorIndex> t = {
        {"Ag", indexOf(kAg)}, {"Al", indexOf(kAl)}, {"Au", indexOf(kAu)}, {"Cr", indexOf(kCr)}, {"Cu", indexOf(kCu)}};
    for (const ConductorTableText& m : kConductorTables)
      t.emplace(m.name, ConductorIndex{spdTable(m.name, m.eta), spdTable(m.name, m.k)});
    return t;
  }();
  return table;
}

}  // namespace

std::optional<ConductorIndex> conductorIndex(const std::string& name) {
  auto it = materials().find(name);
  if (it == materials().end()) return std::nullopt;
  return it->second;
}

std::string conductorNames() {
  std::string names;
  for (const auto& [name, index] : materials()) names += (names.empty() ? "" : ", ") + name;
  return names;
}

}  // namespace columba
