// A POV-Ray `light_source { … }` statement read into a LightDesc. Part of the scene builder (scene_builder.cpp).
#pragma once

#include <functional>
#include <vector>

#include "raytrace/parse/povray/surface_reader.hpp"
#include "raytrace/scene/description.hpp"

namespace rt::povray {

// What the scene builder does with a light's looks_like object: draw it about the light's `position`, moved by
// the light's transforms `steps` (POV-Ray 3.7 manual, "Looks_like").
using LooksLike =
    std::function<void(const Node& looksLike, const glm::dvec3& position, const std::vector<TransformStep>& steps)>;

// What the scene builder does with a light's projected_through block: keeps its object for the light.
using ProjectedThrough = std::function<void(const Node& block)>;

// A light's items into `l`, moved by its transforms: an identifier's first, then the ones that follow it.
void readLight(const Node& n, LightDesc& l, ReadingContext& context, const LooksLike& looksLikeAt,
               const ProjectedThrough& projectedThrough);

// The light moved by `m`: its position, its spotlight's point_at, its parallel light's point and its area's axes.
void moveLight(LightDesc& l, const glm::dmat4& m);

}  // namespace rt::povray
