/*! plugin volume gridvolume
Values on a grid of voxels read from a Mitsuba grid volume file (`.vol`: one channel, a value at every wavelength, or three, a linear sRGB colour that becomes a smooth spectrum per voxel, twice its largest component times the spectrum of the colour scaled to 1/2 there, as Mitsuba upsamples one), over the unit cube that `to_world` places in the scene. Voxel values lie at the voxels' centres and are interpolated trilinearly; within half a voxel of a face the neighbour is the face's own voxel (`clamp`, and `mirror`, which reflects onto the same voxel) or the opposite face's (`repeat`). Outside the cube the volume is empty. A medium tracks collisions against a majorant grid: the cube is cut into cells (half a voxel each along an axis of up to 8 voxels, else 16 along it), each bounded by the largest voxel its filter reaches, so a few dense voxels slow the tracking only near themselves.
Mitsuba 3: `raw` true with three channels is refused; where `to_world` rotates, the volume is the rotated cube, not the box around it.
| parameter | type | default | meaning | Mitsuba 3 |
| filename | string | — | the `.vol` file (float32 values; 1 or 3 channels) | same |
| filter_type | string | `trilinear` | `trilinear` or `nearest` (the value of the voxel containing the point) | same |
| to_world | transform | identity | places the unit cube [0, 1]³ in the scene | same |
| use_grid_bbox | boolean | false | true: the unit cube is first mapped onto the bounding box the file's header gives, then placed by `to_world` | same |
| wrap_mode | string | `clamp` | `clamp`, `repeat` or `mirror`: the neighbour of a voxel on a face, for the trilinear filter | same |
| max_value | float | the grid's largest value | a bound on the values, checked (one below the grid's largest value is warned about) but not used: the majorant grid's cells are bounded by the voxels | the majorant, taken as given |
| raw | boolean | false | must be false for three channels (they are always upsampled) | `true` keeps the three channels as given |
*/
#include "media/grid_volume.h"

#include <fmt/format.h>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/error.h"
#include "core/rgb_spectrum_table.h"

namespace columba {

GridVolume::GridVolume(const VolumeGrid& grid, Filter filter, Wrap wrap, const Transform& toWorld)
    : Volume(toWorld), xres_(grid.xres), yres_(grid.yres), zres_(grid.zres), filter_(filter), wrap_(wrap) {
  // Extinctions and albedos are not negative, and a colour's spectrum is twice its largest
  // component, which must stay finite; the first value out of range is named.
  constexpr float kLargest = 0.25f * std::numeric_limits<float>::max();
  for (size_t i = 0; i < grid.values.size(); ++i)
    if (grid.values[i] < 0.0f || grid.values[i] > kLargest) {
      const size_t voxel = i / size_t(grid.channels), x = voxel % size_t(xres_),
                   y = voxel / size_t(xres_) % size_t(yres_), z = voxel / size_t(xres_) / size_t(yres_);
      throw std::invalid_argument("the value at x " + std::to_string(x) + ", y " + std::to_string(y) + ", z " +
                                  std::to_string(z) + ", channel " + std::to_string(i % size_t(grid.channels)) +
                                  " is " + fmt::format("{:g}", grid.values[i]) +
                                  "; a volume's values must lie in [0, " + fmt::format("{:g}", kLargest) + "]");
    }
  for (float v : grid.values) largestGiven_ = std::max(largestGiven_, v);
  if (grid.channels == 1) {
    values_ = grid.values;
  } else if (grid.channels == 3) {
    // Each voxel's spectrum from the table of fits, as an environment map's pixels get theirs.
    spectra_ = tabulatedRGBSpectra(grid.values.data(), grid.values.size() / 3);
  } else {
    throw std::invalid_argument("the grid has " + std::to_string(grid.channels) +
                                " channels; a volume takes 1 (a value) or 3 (an RGB colour)");
  }
  for (size_t i = 0; i < size_t(xres_) * size_t(yres_) * size_t(zres_); ++i) max_ = std::max(max_, voxelBound(i));
}

float GridVolume::maxValue(const Vec3& lo, const Vec3& hi) const {
  // The voxels each axis reaches from lo to hi. Trilinear: a point x voxels along blends the
  // voxels whose centres lie either side of it, floor(x - 1/2) and the next, so the box reaches
  // from floor(lo - 1/2) to ceil(hi - 1/2) (a voxel on the box's face with weight 0 left out).
  // Nearest: the voxel holding the point, floor(lo) to ceil(hi) - 1. Clamp takes the range to
  // the grid; repeat wraps it round.
  const int res[3] = {xres_, yres_, zres_};
  std::vector<int> reached[3];
  for (int a = 0; a < 3; ++a) {
    const double from = double(lo[a]) * res[a], to = double(hi[a]) * res[a];
    const double first = filter_ == Filter::Trilinear ? std::floor(from - 0.5) : std::floor(from);
    const double last = std::max(first, filter_ == Filter::Trilinear ? std::ceil(to - 0.5) : std::ceil(to) - 1.0);
    if (wrap_ == Wrap::Repeat && last - first + 1.0 >= res[a]) {
      for (int i = 0; i < res[a]; ++i) reached[a].push_back(i);
      continue;
    }
    if (wrap_ == Wrap::Repeat) {
      for (double i = first; i <= last; ++i) reached[a].push_back(int(i - res[a] * std::floor(i / res[a])));
      continue;
    }
    for (int i = int(std::clamp(first, 0.0, double(res[a] - 1))); i <= int(std::clamp(last, 0.0, double(res[a] - 1)));
         ++i)
      reached[a].push_back(i);
  }
  float largest = 0.0f;
  for (int z : reached[2])
    for (int y : reached[1])
      for (int x : reached[0])
        largest = std::max(largest, voxelBound((size_t(z) * size_t(yres_) + size_t(y)) * size_t(xres_) + size_t(x)));
  return largest;
}

std::array<int, 3> GridVolume::majorantResolution() const {
  std::array<int, 3> cells{};
  const int res[3] = {xres_, yres_, zres_};
  for (int a = 0; a < 3; ++a) cells[a] = res[a] <= 8 ? 2 * res[a] : 16;
  return cells;
}

Spectrum GridVolume::voxel(int x, int y, int z, const Wavelengths& wl) const {
  const size_t i = (size_t(z) * size_t(yres_) + size_t(y)) * size_t(xres_) + size_t(x);
  if (spectra_.empty()) return Spectrum(values_[i]);
  Spectrum s;
  for (int k = 0; k < kSpectrumSamples; ++k) s[k] = spectra_[i].eval(wl[k]);
  return s;
}

namespace {
// x taken into [0, n) by whole periods n, without converting a large x to int.
float wrapped(float x, int n) {
  const float period = float(n), r = x - period * std::floor(x / period);
  return r < period ? r : 0.0f;
}
}  // namespace

Spectrum GridVolume::evalLocal(const Vec3& p, const Wavelengths& wl) const {
  const int res[3] = {xres_, yres_, zres_};
  if (filter_ == Filter::Nearest) {
    int cell[3];
    for (int a = 0; a < 3; ++a) {
      const float x = p[a] * float(res[a]);
      cell[a] = wrap_ == Wrap::Repeat ? std::min(int(wrapped(x, res[a])), res[a] - 1)
                                      : int(std::clamp(std::floor(x), 0.0f, float(res[a] - 1)));
    }
    return voxel(cell[0], cell[1], cell[2], wl);
  }
  // Voxel values sit at the voxels' centres: the point in units of voxels, half a voxel back.
  int lo[3], hi[3];
  float w[3];
  for (int a = 0; a < 3; ++a) {
    if (wrap_ == Wrap::Repeat) {
      // Half a voxel from a face, the neighbour is the opposite face's voxel; the grid tiles space.
      const float x = wrapped(p[a] * float(res[a]) - 0.5f, res[a]);
      lo[a] = std::min(int(x), res[a] - 1);
      hi[a] = (lo[a] + 1) % res[a];
      w[a] = x - float(lo[a]);
      continue;
    }
    const float x = std::clamp(p[a] * float(res[a]) - 0.5f, 0.0f, float(res[a] - 1));
    lo[a] = std::min(int(x), res[a] - 1);
    hi[a] = std::min(lo[a] + 1, res[a] - 1);
    w[a] = x - float(lo[a]);
  }
  // One channel: the values interpolated. Three: each voxel's spectrum is a shape (the smooth
  // spectrum of its colour over twice its largest component, within [0, 1]) times that scale;
  // shapes and scales are interpolated apart and multiplied, as Mitsuba's grid does.
  Spectrum sum(0.0f);
  float scale = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    float weight = 1.0f;
    int at[3];
    for (int a = 0; a < 3; ++a) {
      const bool upper = corner >> a & 1;
      at[a] = upper ? hi[a] : lo[a];
      weight *= upper ? w[a] : 1.0f - w[a];
    }
    if (!(weight > 0.0f)) continue;
    if (spectra_.empty()) {
      sum += voxel(at[0], at[1], at[2], wl) * weight;
      continue;
    }
    const float voxelScale =
        spectra_[(size_t(at[2]) * size_t(yres_) + size_t(at[1])) * size_t(xres_) + size_t(at[0])].scale;
    scale += weight * voxelScale;
    if (voxelScale > 0.0f) sum += voxel(at[0], at[1], at[2], wl) * (weight / voxelScale);
  }
  return spectra_.empty() ? sum : sum * scale;
}

std::shared_ptr<Object> makeGridVolume(const Properties& props) {
  const std::string filterName = props.getString("filter_type", "trilinear");
  if (filterName != "trilinear" && filterName != "nearest")
    throw props.error("filter_type", "filter_type must be 'trilinear' or 'nearest', not '" + filterName + "'");
  const std::string wrap = props.getString("wrap_mode", "clamp");
  if (wrap != "clamp" && wrap != "repeat" && wrap != "mirror")
    throw props.error("wrap_mode", "wrap_mode must be 'clamp', 'repeat' or 'mirror', not '" + wrap + "'");
  const bool raw = props.getBool("raw", false);
  const std::string path = props.getPath("filename");
  VolumeGrid grid;
  try {
    grid = readVolumeGrid(path);
  } catch (const InputError& e) {
    throw props.error("filename", e.what());
  }
  if (raw && grid.channels == 3)
    throw props.error("raw", path + ": raw three-channel grids are not supported (a spectral renderer upsamples them)");
  Transform toWorld = props.getTransform("to_world");
  if (props.getBool("use_grid_bbox", false)) {
    // The unit cube is mapped onto the header's box before to_world places it, as Mitsuba does.
    Vec3 lo, extent;
    for (int a = 0; a < 3; ++a) {
      lo[a] = grid.boundsMin[a];
      extent[a] = grid.boundsMax[a] - grid.boundsMin[a];
      if (!std::isfinite(lo[a]) || !std::isfinite(extent[a]) || !(extent[a] >= std::numeric_limits<float>::min()))
        throw props.error("use_grid_bbox", fmt::format("{}: the header's bounding box ({}, {}, {}) to ({}, {}, {}) is "
                                                       "empty or not finite",
                                                       path, grid.boundsMin[0], grid.boundsMin[1], grid.boundsMin[2],
                                                       grid.boundsMax[0], grid.boundsMax[1], grid.boundsMax[2]));
    }
    toWorld = toWorld * Transform::translate(lo) * Transform::scale(extent);
  }
  std::shared_ptr<GridVolume> volume;
  try {
    volume = std::make_shared<GridVolume>(
        grid, filterName == "nearest" ? GridVolume::Filter::Nearest : GridVolume::Filter::Trilinear,
        wrap == "repeat" ? GridVolume::Wrap::Repeat : GridVolume::Wrap::Clamp, toWorld);
  } catch (const std::invalid_argument& e) {
    throw props.error("filename", path + ": " + e.what());
  }
  if (props.has("max_value")) {
    // Mitsuba tracks against max_value; here each cell of the majorant grid is bounded by the
    // voxels it reaches, so a bound from the scene is only checked.
    const float bound = props.getFloat("max_value");
    if (!(bound >= 0.0f) || !std::isfinite(bound))
      throw props.error("max_value", "max_value must be a finite number, not negative, not " + std::to_string(bound));
    if (bound < volume->maxValue())
      warn(props.locationOf("max_value"),
           fmt::format("max_value {:g} is below the grid's largest value {:g}; the majorants are taken from the "
                       "grid's values (a smaller one would bias the tracking)",
                       bound, volume->maxValue()));
  }
  return volume;
}

}  // namespace columba
