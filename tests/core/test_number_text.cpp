// listNumbers, the one reader of the number lists scenes give as text (tabphase's values,
// barbulearms' tilts): commas and white space separate, an empty place between commas is an error
// naming the text and the item, as is an item that is not a finite number.
#include <gtest/gtest.h>

#include <stdexcept>

#include "core/number_text.h"
#include "support/error_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {
std::string listError(const std::string& text) {
  try {
    listNumbers(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(ListNumbers, CommasAndWhiteSpaceSeparateAndEmptyPlacesAreErrors) {
  EXPECT_EQ(listNumbers("1, 2.5,-3"), (std::vector<double>{1.0, 2.5, -3.0}));
  EXPECT_EQ(listNumbers(" 1 2\t3 "), (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_EQ(listNumbers("1 2, 3"), (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_TRUE(listNumbers("").empty());
  expectContains(listError("1,,2"), {"'1,,2'", "empty place between its commas", "item 2"});
  expectContains(listError("1, ,2"), {"'1, ,2'", "item 2"});
  expectContains(listError(",1"), {"item 1", "before the first comma"});
  expectContains(listError("1,2,"), {"item 3"});
  expectContains(listError("1, 2x, 3"), {"'1, 2x, 3'", "item 2", "'2x'", "is not a number"});
  expectContains(listError("1e400"), {"'1e400'", "is not a number"});
}
