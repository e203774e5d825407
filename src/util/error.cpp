#include "raytrace/util/error.hpp"

#include <mutex>
#include <set>

namespace rt {

FileName::FileName(const std::string& name) {
  // A std::set never moves its elements, so the pointers stay valid as names are added.
  static std::set<std::string> names;
  static std::mutex guard;
  const std::lock_guard<std::mutex> lock(guard);
  name_ = &*names.insert(name).first;
}

const std::string& FileName::str() const {
  static const std::string none;
  return name_ ? *name_ : none;
}

}  // namespace rt
