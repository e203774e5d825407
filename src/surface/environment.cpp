#include "raytrace/surface/environment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt {

Color SkySphere::at(const glm::dvec3& dir, const Color& background) const {
  const glm::dvec3 p = glm::normalize(glm::dvec3(fromWorld * glm::dvec4(dir, 0)));
  Color c = background;
  // Each layer over the ones below it, as a texture's layers (Texture::at).
  for (const auto& layer : layers) {
    const Rgbft top = layer->at(p);
    const Color through = filterTints ? top.filter * top.rgb + Color(top.transmit) : Color(top.filter + top.transmit);
    c = top.rgb * (1 - top.filter - top.transmit) + c * through;
  }
  return c;
}

Color SkySphere::bound() const {
  Color b(0);
  for (const auto& layer : layers) {
    anyColour(*layer, [&](const Rgbft& c) {
      b = glm::max(b, c.rgb);
      return false;
    });
  }
  return b;
}

namespace {

// ∫ density dh from h0 to h1 (h0 ≤ h1) of the ground fog's density: 1 up to `offset`, then
// 1/(1 + ((h − offset)/alt)²), whose antiderivative is alt·atan((h − offset)/alt). The manual's "25% at
// offset + alt" is not what POV-Ray 3.7 draws: its pictures give half (docs/povray-language.md, "Fog").
double densityIntegral(double h0, double h1, double offset, double alt) {
  double sum = 0;
  if (h0 < offset) {
    sum += std::min(h1, offset) - h0;
    h0 = offset;
  }
  if (h1 <= h0) return sum;
  if (alt <= 0) return sum;  // no fog above the offset
  const auto antiderivative = [&](double h) { return alt * std::atan((h - offset) / alt); };
  return sum + antiderivative(h1) - antiderivative(h0);
}

}  // namespace

double Fog::turbulentShare(const glm::dvec3& origin, const glm::dvec3& dir, double depth) const {
  // Measured on POV-Ray 3.7's pictures (docs/povray-language.md, "Fog"): the turbulence sum T at the ray's
  // midpoint, scaled by the turbulence amount, thins the fog by min(turb_depth·T, 1) times the constant
  // fog's transmittance over the depth, whatever the fog's type.
  const glm::dvec3 p = (origin + 0.5 * depth * dir) * turbulence.amount;
  const double u = std::min(turbDepth * turbulenceSum(p, turbulence, noise.get()), 1.0);
  return 1 - u * std::exp(-depth / distance);
}

Fog::Effect Fog::effect(const glm::dvec3& origin, const glm::dvec3& dir, double depth) const {
  if (distance <= 0) return {Color(1), Color(0)};  // POV-Ray treats a zero distance as no fog
  double thickness = depth;
  if (type == Type::Ground) {
    const double h0 = glm::dot(origin, up), k = glm::dot(dir, up);
    if (std::abs(k) < 1e-12) {
      thickness = h0 <= offset ? depth : alt > 0 ? depth / (1 + std::pow((h0 - offset) / alt, 2)) : 0;
    } else {
      const double h1 = std::isinf(depth) ? std::copysign(std::numeric_limits<double>::infinity(), k) : h0 + k * depth;
      thickness = densityIntegral(std::min(h0, h1), std::max(h0, h1), offset, alt) / std::abs(k);
    }
  }
  if (turbulence.on() && std::isfinite(depth)) thickness *= turbulentShare(origin, dir, depth);
  const float kept = std::isinf(thickness) ? 0.0f : float(std::exp(-thickness / distance));
  // The fog's transmit is the share of light it always lets through; its filter tints what it lets through
  // by its colour. Fitted to POV-Ray 3.7's pictures (docs/povray-language.md, "Fog").
  const float opacity = (1 - kept) * (1 - colour.transmit);
  return {(1 - opacity) * (Color(1 - colour.filter) + colour.filter * colour.rgb), opacity * colour.rgb};
}

Color Fog::over(const Color& c, const glm::dvec3& origin, const glm::dvec3& dir, double depth) const {
  const Effect e = effect(origin, dir, depth);
  return c * e.through + e.added;
}

Color throughFogs(const std::vector<Fog>& fogs, Color c, const glm::dvec3& origin, const glm::dvec3& dir, double depth) {
  Color added(0);
  for (const Fog& f : fogs) {
    const Fog::Effect e = f.effect(origin, dir, depth);
    c *= e.through;
    added += e.added;
  }
  return c + added;
}

}  // namespace rt
