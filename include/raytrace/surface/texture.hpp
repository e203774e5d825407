// A texture: the material at each point of a surface, for shading to read in place of one constant. An object
// without one has its Material everywhere, the only kind the course and .cli scenes have.
#pragma once

#include "raytrace/geometry/math.hpp"
#include "raytrace/surface/material.hpp"

namespace rt {

class Texture {
 public:
  virtual ~Texture() = default;
  // The material at the world point p of the surface. Patterns are evaluated in double whatever the scene's
  // arithmetic: their noise and their bands repeat at scales float cannot place.
  virtual Material at(const glm::dvec3& p) const = 0;
  // A material whose every term is at least as bright as the texture's anywhere: what the tracer bounds the
  // light a ray can return with (render/tracer).
  virtual Material brightest() const = 0;
};

}  // namespace rt
