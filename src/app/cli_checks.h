#pragma once
// What the command line shares: names suggested for misspelt commands and options, the check
// that every floating-point option is a finite number, and whole-number options read alike.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace columba {

// The name in `candidates` closest to `given` (edit distance), or "" if none is close enough to
// be a plausible misspelling.
std::string closestName(const std::string& given, const std::vector<std::string>& candidates);

// Adds to every floating-point option of `app` and its subcommands a check that rejects NaN and
// infinities ("--mu: must be a finite number, not 'nan'").
void requireFiniteNumbers(CLI::App& app);

// Every name by which `command`'s options can be given ("-o", "--output", ...).
std::vector<std::string> optionNames(const CLI::App& command);

// A whole number given for `option` as `text`, between `lowest` and `highest`, or 0 if it was
// not given; every mistake gets the same message, whichever option it is.
int parseCount(const char* option, const std::string& text, int lowest, int highest);

}  // namespace columba
