#include "core/name_table.h"

namespace columba {

int NameTable::idOf(std::string_view name) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return int(i);
  names_.emplace_back(name);
  return int(names_.size() - 1);
}

}  // namespace columba
