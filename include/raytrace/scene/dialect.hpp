// The shading rules of a scene language, where the languages part: how a reflection is weighed and tinted, what
// a ray at the depth limit returns, whether each bounce is clamped, whether shadows pass transparent surfaces,
// and how a pixel's colour becomes a byte. Each parser chooses its language's dialect; the tracer asks it through
// inline methods over these few values, so a hit pays no virtual call.
#pragma once

#include <algorithm>

#include "raytrace/geometry/math.hpp"

namespace rt {

class Dialect {
 public:
  // How a pixel's colour c becomes a byte: round(c·255), (int)(c·255), or round(sRGB(c)·255).
  enum class ToByte { Round, Truncate, Srgb };

  // The course's POV subset (docs/reference/csc473.md): reflected light tinted by the pigment and taking its
  // share from the surface's own (§c.3, §c.5); six rays deep (§c.9); bytes rounded (§a.0).
  static Dialect course() { return Dialect(); }

  // CS 3451's .cli language, as its reference images require (docs/reference/cs3451.md §A.4): bytes truncated
  // (§A.4.2); reflection added to the local colour, weighted by Krefl alone, every shade clamped to [0, 1], and
  // reflected rays 1 to 9 of which the 9th returns black when it hits (§A.4.5).
  static Dialect cs3451() {
    Dialect d;
    d.toByte_ = ToByte::Truncate;
    d.reflectionReplacesLocal_ = false;
    d.reflectionTakesPigment_ = false;
    d.clampsEachBounce_ = true;
    d.depthLimit_ = 9;
    d.shadesAtDepthLimit_ = false;
    return d;
  }

  // POV-Ray 3.7 (docs/povray-language.md): reflected light added to the surface's own, untinted and whole
  // however transparent the surface (manual, "Specular Reflection"; measured); light through a transparent
  // surface tinted at each surface it crosses, in eye rays as in shadows (measured); five levels
  // (manual, "Max_Trace_Level"). `gamma` is the scene's assumed_gamma: the sRGB of each pixel's colour raised to
  // it is written, or, at 0 (a scene before #version 3.7 without assumed_gamma), the colours as they are,
  // rounded (docs/povray-language.md, "Gamma").
  static Dialect povray(double gamma) {
    Dialect d;
    d.reflectionReplacesLocal_ = false;
    d.reflectionTakesPigment_ = false;
    d.transparencyDimsReflection_ = false;
    d.filtersShadows_ = true;
    d.tintsEachCrossing_ = true;
    d.totalReflectionWhole_ = true;
    if (gamma > 0) {
      d.toByte_ = ToByte::Srgb;
      d.gamma_ = float(gamma);
    }
    return d;
  }

  ToByte toByte() const { return toByte_; }
  // What each pixel's colour c is raised to before it is written: c^gamma, whose bytes are toByte's.
  float gamma() const { return gamma_; }

  // Whether reflected light takes its share k from the surface's own light, local·(1−f)(1−k) + k·reflected,
  // or is added to all of it, local·(1−f) + k·reflected (render/shading.hpp, Weights).
  bool reflectionReplacesLocal() const { return reflectionReplacesLocal_; }
  // The tint on reflected light at a surface of this pigment.
  Color reflectionTint(const Color& pigment) const { return reflectionTakesPigment_ ? pigment : Color(1); }
  // Whether a surface's reflection k counts for its opaque share alone, (1−f)·k, or whole (render/shading.hpp,
  // Weights).
  bool transparencyDimsReflection() const { return transparencyDimsReflection_; }
  // The tint on light a surface of this pigment lets through: on the way into its object alone (the course:
  // transmitted light takes the colour of the object it travelled in, §c.4), or at every surface crossed.
  Color transmissionTint(const Color& pigment, bool entering) const {
    return entering || tintsEachCrossing_ ? pigment : Color(1);
  }

  // Whether a transparent surface that reflects all the light through it (total internal reflection) reflects
  // with weight 1, untinted, whatever its reflection, filter and transmit (POV-Ray: measured,
  // docs/povray-language.md), or adds the share it lets through to its reflection (§c.4).
  bool totalReflectionWhole() const { return totalReflectionWhole_; }

  // What a ray's colour becomes before the level above weighs it, and the largest it can be for a colour whose
  // largest channel is at most `brightest`.
  Color bounced(const Color& c) const { return clampsEachBounce_ ? glm::clamp(c, 0.0f, 1.0f) : c; }
  float bounced(float brightest) const { return clampsEachBounce_ ? std::min(brightest, 1.0f) : brightest; }

  // The deepest secondary ray traced (the eye ray is depth 0), unless the scene or the command line sets it.
  int depthLimit() const { return depthLimit_; }
  // Whether a ray at the depth limit that hits a surface is shaded; if not it returns black.
  bool shadesAtDepthLimit() const { return shadesAtDepthLimit_; }

  // Whether light reaches a point through transparent surfaces, tinted by each; if not, any surface stops it.
  bool filtersShadows() const { return filtersShadows_; }

 private:
  Dialect() = default;  // the course's: course()
  ToByte toByte_ = ToByte::Round;
  float gamma_ = 1;
  bool reflectionReplacesLocal_ = true;
  bool reflectionTakesPigment_ = true;
  bool transparencyDimsReflection_ = true;
  bool tintsEachCrossing_ = false;
  bool totalReflectionWhole_ = false;
  bool clampsEachBounce_ = false;
  int depthLimit_ = 5;
  bool shadesAtDepthLimit_ = true;
  bool filtersShadows_ = false;
};

}  // namespace rt
