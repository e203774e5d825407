#include "raytrace/scene/arithmetic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt {

namespace {

bool courseTierSound(const SceneDesc& scene, const SceneScale& s, const TierDomain& d) {
  return scene.language == SceneLanguage::Pov && s.smallestFeature >= kCourseMinFeature &&
         s.extent <= kCourseMaxExtent && s.largestTransform <= kCourseMaxExtent &&
         d.textbookPixels <= kVisiblePixels &&
         d.textbookHitError <= kCourseEpsilon / 4 && d.offsetShadowPixels <= kVisiblePixels &&
         d.offsetRefractionPixels <= kVisiblePixels && smallestGap(scene) >= 2 * kCourseEpsilon;
}

// Whether float's error is bounded, and tested, on every kind of shape in the scene (shapes/kind.hpp). A clip
// decides by inside tests at points of another surface, as CSG does: not bounded yet.
bool floatErrorBounded(const SceneDesc& scene) {
  return std::all_of(scene.objects.begin(), scene.objects.end(), [](const ObjectDesc& o) {
    return o.clip.empty() && std::visit([](const auto& k) { return k.kFloatErrorBound; }, o.shape);
  });
}

}  // namespace

Arithmetic chooseArithmetic(const SceneDesc& scene, Arithmetic requested, View view) {
  Arithmetic a = requested;
  if (a.tier != Tier::Auto && a.sphere != SphereMethod::Auto && a.offset) return a;
  const SceneScale s = sceneScale(scene);
  const double r = precisionBudget(s);
  const TierDomain d = tierDomain(scene, view);
  if (a.tier == Tier::Auto) {
    const bool floatSound = r <= 1e4 && d.robustPixels <= kVisiblePixels;
    a.tier = !floatErrorBounded(scene)       ? Tier::Double
             : courseTierSound(scene, s, d) ? Tier::Course
             : floatSound                   ? Tier::Float
                                            : Tier::Double;
  }
  if (a.sphere == SphereMethod::Auto) {
    const bool textbook =
        a.tier == Tier::Course || (a.tier == Tier::Float && r <= 50 && d.textbookPixels <= kVisiblePixels);
    a.sphere = textbook ? SphereMethod::Textbook : SphereMethod::Robust;
  }
  if (!a.offset) a.offset = a.tier == Tier::Course ? OffsetPolicy::Course : OffsetPolicy::Relative;
  return a;
}

}  // namespace rt
