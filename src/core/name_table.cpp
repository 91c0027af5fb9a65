#include "core/name_table.h"

namespace columba {

int NameTable::idOf(std::string_view name) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return int(i);
  names_.emplace_back(name);
  return int(names_.size() - 1);
}

int NameTable::find(std::string_view name) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return int(i);
  return -1;
}

std::string NameTable::nameOf(int id) {
  std::lock_guard<std::mutex> lock(mutex_);
  return names_.at(size_t(id));
}

}  // namespace columba
