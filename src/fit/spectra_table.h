#pragma once
// Measured reflectance spectra as biologists keep them, read into samples of directions,
// wavelength and reflectance factor: Columba's long layout (a row per direction pair and
// wavelength), and wide layouts with a wavelength column and one column per spectrum (pavo's,
// a two-column spectrum, and `columba bsdf --mode specular`'s table), whose geometry is given
// separately or, for columba bsdf's, read from the column names.
#include <string>
#include <vector>

namespace columba {

// One sample: directions in degrees (theta from the vane normal, phi from the axis across the
// barbules), the wavelength in nm and the reflectance factor.
struct SpectraSample {
  float thetaI = 0, phiI = 0, thetaO = 0, phiO = 0, wavelength = 0, reflectance = 0;
};

// Where a spectrum without directions of its own was measured: light at polar angle theta_i
// (degrees; one for every spectrum column, or one each) and azimuth phi_i, seen in the mirror
// direction (theta_i, phi_i + 180) or along the vane normal.
struct SpectraGeometry {
  enum class View { Mirror, Normal };
  std::vector<float> thetaI;
  float phiI = 0.0f;
  View view = View::Mirror;
};

// Reads a CSV ('#' lines are comments, a UTF-8 byte-order mark is skipped) with a header:
// - long: columns theta_i, phi_i, theta_o, phi_o, wavelength_nm, reflectance (any order, others
//   ignored); a row whose omega_o is omega_i itself (phi_o = phi_i) gets a warning, as that is
//   the retro direction, not the mirror one (phi_o = phi_i + 180);
// - wide: a wavelength column (wavelength_nm, wavelength, wl, lambda or nm) and one column per
//   spectrum. Columns named total_thetaA (columba bsdf --mode specular) are the mirror direction at
//   theta_i = A, phi_i from `geometry` (R_thetaA and TRT_thetaA, its parts, are skipped); other
//   columns take `geometry`.
// Throws InputError naming the file, line and value for anything it cannot read, a spectrum
// without a geometry among them.
std::vector<SpectraSample> readSpectraCSV(const std::string& path, const SpectraGeometry& geometry = {});

}  // namespace columba
