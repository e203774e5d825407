// The course's text output formats (csc473-course.md §a): fixed notation, 4 decimals, `{x y z}` vectors.
#pragma once

#include <ostream>
#include <string>

#include <glm/glm.hpp>

#include "raytrace/scene/description.hpp"

namespace rt {

std::string fixed4(double v);                      // "12.0001", "-0.0000"
std::string braces(const glm::dvec3& v);          // "{x y z}"
std::string bare(const glm::dvec3& v);            // "x y z"

// `sceneinfo`: camera, lights and objects as the course lists them (§a.1).
void printSceneInfo(std::ostream& out, const SceneDesc& scene);

}  // namespace rt
