#include "raytrace/render/shading.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace rt {

namespace {

float saturate(float x) { return glm::clamp(x, 0.0f, 1.0f); }

// e^−107 < 2^−154: far below 2^−150, half the smallest subnormal float, under which powf rounds to +0.
constexpr float kUnderflowExponent = 107.0f;

// Smith's masking term for GGX, G1(x) = 2 / (1 + √(1 + α² tan²θx)) (Walter et al. 2007, eq. 34). The caller
// has checked x·n > 0, and the half vector makes x·h ≥ 0, so the χ⁺(x·h / x·n) of §c.2 is 1. A tiny x·n
// gives tan²θ = ∞ and G1 = 0, never NaN.
float smithG1(float xn, float alpha) {
  const float tan2 = (1.0f - xn * xn) / (xn * xn);
  return 2.0f / (1.0f + std::sqrt(1.0f + alpha * alpha * tan2));
}

}  // namespace

template <class T>
float blinnPhongSpecular(const Vec3<T>& n, const Vec3<T>& v, const Vec3<T>& l, float exponent) {
  const Vec3<T> sum = l + v;
  const T len = glm::length(sum);
  if (!(len > T(0))) return 0.0f;  // l = −v: no half vector
  const float nh = saturate(float(glm::dot(n, sum) / len));
  // nh^p ≤ e^(−p(1 − nh)) (ln x ≤ x − 1): past kUnderflowExponent that is below 2^−154, which powf rounds to
  // +0, so the answer is the same without powf's slow underflow path (docs/performance-notes.md).
  if ((1.0f - nh) * exponent > kUnderflowExponent) return 0.0f;
  return std::pow(nh, std::max(exponent, 0.0f));
}

template <class T>
float phongSpecular(const Vec3<T>& n, const Vec3<T>& v, const Vec3<T>& l, float exponent) {
  const Vec3<T> r = T(2) * glm::dot(n, v) * n - v;
  const float rl = saturate(float(glm::dot(r, l)));
  if ((1.0f - rl) * exponent > kUnderflowExponent) return 0.0f;  // as in blinnPhongSpecular
  return std::pow(rl, std::max(exponent, 0.0f));
}

template <class T>
float cookTorranceSpecular(const Vec3<T>& n, const Vec3<T>& v, const Vec3<T>& l, float roughness, float ior) {
  const float nl = float(glm::dot(n, l));
  const float nv = float(glm::dot(n, v));
  // Light or viewer below the surface: χ⁺ in G makes the whole term 0 (§c.2).
  if (!(nl > 0.0f && nv > 0.0f)) return 0.0f;
  const Vec3<T> h = glm::normalize(l + v);  // l + v ≠ 0: both lie above the surface
  const float alpha = ggxAlpha(roughness);
  const float nh = saturate(float(glm::dot(n, h)));
  const float a2 = alpha * alpha;
  // D's denominator (n·h)²(α² − 1) + 1, written as sin²θh + (n·h)²α² so that it keeps its α² near the peak
  // instead of cancelling to 0 in float (1 − 1 + α²).
  const Vec3<T> across = glm::cross(n, h);
  const float k = float(glm::dot(across, across)) + nh * nh * a2;
  const float d = a2 / (glm::pi<float>() * k * k);
  const float g = smithG1(nv, alpha) * smithG1(nl, alpha);
  const float f = schlick(float(glm::dot(v, h)), ior);
  return d * g * f / (4.0f * std::max(1.0f / 16.0f, nv));
}

float ggxAlpha(float roughness) { return std::max(roughness * roughness, kMinGgxAlpha); }

float schlick(float cosTheta, float ior) {
  const float r = (ior - 1.0f) / (ior + 1.0f);
  const float f0 = r * r;
  return f0 + (1.0f - f0) * std::pow(1.0f - saturate(cosTheta), 5.0f);
}

template <class T> Vec3<T> reflectDirection(const Vec3<T>& d, const Vec3<T>& n) {
  return glm::normalize(d - T(2) * glm::dot(d, n) * n);
}

template <class T> Vec3<T> reflectBent(const Vec3<T>& d, const Vec3<T>& n, const Vec3<T>& side) {
  const Vec3<T> r = reflectDirection(d, n);
  const T into = glm::dot(r, side);
  if (into >= T(0)) return r;
  if (glm::dot(d, n) > T(0)) return reflectDirection(d, side);
  return glm::normalize(r - T(2) * into * side);
}

template <class T> std::optional<Vec3<T>> refractDirection(const Vec3<T>& d, const Vec3<T>& n, float ior) {
  const bool entering = glm::dot(d, n) <= T(0);
  const T eta = entering ? T(1) / T(ior) : T(ior);
  const Vec3<T> facing = entering ? n : -n;  // the normal on the side the ray comes from
  const T cosIn = -glm::dot(d, facing);
  const T k = T(1) - eta * eta * (T(1) - cosIn * cosIn);
  if (k < T(0)) return std::nullopt;
  return glm::normalize(eta * d + (eta * cosIn - std::sqrt(k)) * facing);
}

float fresnelReflectance(float cosTheta, float ior) {
  const float c = std::clamp(cosTheta, 0.0f, 1.0f);
  const float g2 = ior * ior + c * c - 1;
  if (g2 <= 0) return 1;
  const float g = std::sqrt(g2);
  const float a = (g - c) / (g + c), b = (c * (g + c) - 1) / (c * (g - c) + 1);
  return 0.5f * a * a * (1 + b * b);
}

Color variableReflection(const Material& m, float cosTheta) {
  const SurfaceExtras& e = *m.extras;
  const float t = e.reflectionFresnel ? fresnelReflectance(cosTheta, m.ior)
                                      : std::pow(1 - std::clamp(cosTheta, 0.0f, 1.0f), e.reflectionFalloff);
  const Color least = e.reflectionMin * e.reflectionMinTint, most = m.reflection * e.reflectionTint;
  return least + (most - least) * t;
}

Color metallicTint(const Color& pigment, float metallic, float cosTheta) {
  const float x = std::acos(std::clamp(std::abs(cosTheta), 0.0f, 1.0f)) / 1.5707963f;
  const float f = std::clamp(0.014567225f / ((x - 1.12f) * (x - 1.12f)) - 0.011612903f, 0.0f, 1.0f);
  return Color(1) + metallic * (1 - f) * (pigment - Color(1));
}

Color interiorFade(const Material& m, float distance) {
  const SurfaceExtras& e = *m.extras;
  if (!std::isfinite(distance)) return Color(1);
  const float d = distance / e.fadeDistance;
  if (e.fadePower >= 1000) {
    Color kept;
    for (int c = 0; c < 3; ++c) kept[c] = std::exp(-(1 - e.fadeColor[c]) * d);
    return kept;
  }
  const float a = 1 / (1 + std::pow(d, e.fadePower));
  return a + (1 - a) * e.fadeColor;
}

float fakedCaustics(float caustics, float cosTheta) {
  return 1 + std::pow(std::abs(cosTheta), 45 * caustics);
}

Color beerAttenuation(const Color& pigment, float distance) {
  Color kept(1.0f);
  for (int c = 0; c < 3; ++c) {
    // A channel the medium does not absorb (C ≥ 1) keeps everything, even over an infinite path, where
    // 0·∞ would otherwise give NaN; a pigment above 1 does not amplify.
    const float absorbance = std::max(0.0f, 1.0f - pigment[c]) * 0.15f;
    if (absorbance > 0.0f) kept[c] = std::exp(-absorbance * distance);
  }
  return kept;
}

Weights weights(const Material& m, float fresnel, const Dialect& dialect) {
  const float f = m.filter;
  const float k = m.reflection;
  Weights w;
  w.local = (1.0f - f) * (dialect.reflectionReplacesLocal() ? 1.0f - k : 1.0f);
  w.reflection = (dialect.transparencyDimsReflection() ? 1.0f - f : 1.0f) * k + f * fresnel;
  w.transmission = f * (1.0f - fresnel) * (m.extras->conserveEnergy ? 1.0f - k : 1.0f);
  w.reflectionTint = m.extras->reflectionTint;
  return w;
}

template float blinnPhongSpecular(const Vec3<float>&, const Vec3<float>&, const Vec3<float>&, float);
template float blinnPhongSpecular(const Vec3<double>&, const Vec3<double>&, const Vec3<double>&, float);
template float phongSpecular(const Vec3<float>&, const Vec3<float>&, const Vec3<float>&, float);
template float phongSpecular(const Vec3<double>&, const Vec3<double>&, const Vec3<double>&, float);
template float cookTorranceSpecular(const Vec3<float>&, const Vec3<float>&, const Vec3<float>&, float, float);
template float cookTorranceSpecular(const Vec3<double>&, const Vec3<double>&, const Vec3<double>&, float, float);
template Vec3<float> reflectDirection(const Vec3<float>&, const Vec3<float>&);
template Vec3<double> reflectDirection(const Vec3<double>&, const Vec3<double>&);
template Vec3<float> reflectBent(const Vec3<float>&, const Vec3<float>&, const Vec3<float>&);
template Vec3<double> reflectBent(const Vec3<double>&, const Vec3<double>&, const Vec3<double>&);
template std::optional<Vec3<float>> refractDirection(const Vec3<float>&, const Vec3<float>&, float);
template std::optional<Vec3<double>> refractDirection(const Vec3<double>&, const Vec3<double>&, float);

}  // namespace rt
