// The course's text number formats (docs/reference/csc473.md §a): fixed notation, 4 decimals, `{x y z}` vectors;
// and the short form messages quote numbers in.
#pragma once

#include <string>

#include <glm/glm.hpp>

namespace rt {

std::string fixed4(double v);                      // "12.0001", "-0.0000"
std::string braces(const glm::dvec3& v);          // "{x y z}"
std::string bare(const glm::dvec3& v);            // "x y z"
std::string shortest(double v);                    // "%g", for numbers quoted in messages: "0.5", "1e+300"

}  // namespace rt
