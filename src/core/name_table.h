#pragma once
// Names resolved once to small numbers, the same for every use of a name in the program, so that
// what is looked up at each hit compares numbers, not strings. Names are added while scenes are
// built (or at start-up), never per ray; the table is safe to use from several threads.
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace columba {

class NameTable {
 public:
  // The number of `name`, added if it is new: 0, 1, ... in the order names first arrive.
  int idOf(std::string_view name);
  // The number of `name` if it was added, -1 otherwise; and the name of number `id`.
  int find(std::string_view name);
  std::string nameOf(int id);

 private:
  std::mutex mutex_;
  std::vector<std::string> names_;
};

}  // namespace columba
