#pragma once
// Base of everything a scene file instantiates (BSDFs, shapes, emitters, ...).

namespace columba {

class Object {
 public:
  virtual ~Object() = default;
};

}  // namespace columba
