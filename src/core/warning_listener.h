#pragma once
// Where warnings go besides stderr: a front end that has its own channel for them (Python's
// `warnings`) listens, so that a warning about a scene reaches a notebook's user too.
#include <functional>
#include <string>

namespace columba {

// Every warning warn() prints ("FILE:LINE: message", without "warning: ") is also handed to
// `listener`, from whichever thread warned; an empty function stops listening. QuietWarnings
// silences both.
void setWarningListener(std::function<void(const std::string&)> listener);

}  // namespace columba
