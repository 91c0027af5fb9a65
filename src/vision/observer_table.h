#pragma once
// A visual system read from a table of its sensitivities, as biologists keep them (pavo's
// sensdata, a species' published curves): a CSV file of a wavelength column and one column per
// cone, for birds whose parameters are not built in (docs/vision.md, "Observers from a table").
#include <istream>
#include <string>
#include "vision/observer.h"

namespace columba {

// The observer of a table with a header row naming a wavelength column (`wl`, `wavelength`,
// `wavelength_nm` or `lambda`) and cone columns named UVS or VS, SWS, MWS, LWS (at least two) and
// optionally DBL (the double cone); '#' lines are comments; commas, tabs or spaces separate. Each
// curve is interpolated linearly onto the vision grid (300-830 nm, 1 nm), zero outside the table's
// wavelengths, and divided by its area there (area 1, as the built-in observers; in any unit, as the
// column is divided by its largest value first). The receptor noise
// is pavo's coldist default (relative densities UVS/VS 1, SWS 2, MWS 2, LWS 4; Weber fraction 0.1 of
// the longest cone, 0.1 achromatic). The observer is named `name`. Throws InputError naming `path`
// and the line for anything else.
Observer readObserverTable(std::istream& table, const std::string& path, const std::string& name);

// The same from a file (at most 16 MiB), named after the file's stem; or, where the file's header
// starts with `cone`, the observer of the cones' parameters it lists (observer_definition_file.h).
Observer readObserverTableFile(const std::string& path);

// Whether `text` names a table or definition file (it ends in .csv) rather than a built-in observer.
bool namesObserverTable(const std::string& text);
// A built-in observer by its name, or the observer of a table file; throws std::invalid_argument
// for an unknown name (naming the known ones) and InputError for a bad table.
Observer observerNamedOrTabulated(const std::string& nameOrPath);

}  // namespace columba
