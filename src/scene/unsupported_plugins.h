#pragma once
// Mitsuba 3 plug-ins Columba does not have, with what a user should know: a scene naming one gets
// an error that says so (and why, or what to use instead), not just "unknown plug-in".
#include <optional>
#include <string>

namespace columba {

// Why Mitsuba's <tag type="type"> is not available, or nullopt when Mitsuba has no such plug-in.
std::optional<std::string> unsupportedMitsubaPlugin(const std::string& tag, const std::string& type);

}  // namespace columba
