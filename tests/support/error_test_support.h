#pragma once
// Checks of error messages: that an InputError was thrown and names every expected part.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

namespace columba::testing {

// `message` is that of an InputError ("" when none was thrown) and contains every one of `parts`.
inline void expectContains(const std::string& message, std::initializer_list<const char*> parts) {
  EXPECT_FALSE(message.empty()) << "no InputError was thrown";
  for (const char* part : parts)
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

}  // namespace columba::testing
