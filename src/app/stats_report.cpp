#include "raytrace/app/stats_report.hpp"

#include <cmath>
#include <cstdio>

namespace rt {

namespace {

// Milliseconds as both forms print them, to a tenth.
std::string ms(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", seconds * 1000);
  return text;
}

// Millions of rays per second of tracing, to a hundredth.
std::string rate(const RenderStats& s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", s.trace > 0 ? double(s.rays.total()) / s.trace / 1e6 : 0.0);
  return text;
}

double total(const RenderStats& s) { return s.load + s.build + s.trace + s.write; }

// Eye rays per pixel: whole, or a mean to two decimals.
std::string perPixel(double rays) {
  if (rays == std::floor(rays)) return std::to_string(uint64_t(rays));
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", rays);
  return text;
}

}  // namespace

std::string statsText(const RenderStats& s) {
  const auto n = [](uint64_t v) { return std::to_string(v); };
  std::string text = "raytrace: load " + ms(s.load) + " ms, build " + ms(s.build) + " ms, trace " + ms(s.trace) +
                     " ms, write " + ms(s.write) + " ms, total " + ms(total(s)) + " ms (" + n(s.width) + "x" +
                     n(s.height) + ", " + perPixel(s.eyeRays) + (s.eyeRays == 1 ? " eye ray" : " eye rays") +
                     " per pixel, " + n(s.threads) + (s.threads == 1 ? " thread)\n" : " threads)\n");
  text += "raytrace: rays " + n(s.rays.eye) + " eye, " + n(s.rays.gather) + " gather, " + n(s.rays.shadow) +
          " shadow, " + n(s.rays.secondary) + " secondary; " + rate(s) + " M rays/s in trace\n";
  if (s.cache) {
    text += "raytrace: irradiance cache " + n(s.rays.cacheRecords) + " records, " + n(s.rays.cacheLookups) +
            " lookups, " + n(s.rays.cacheMisses) + " gathered uncached\n";
  }
  return text;
}

std::string statsJson(const RenderStats& s) {
  const auto n = [](uint64_t v) { return std::to_string(v); };
  std::string json = "{\"width\": " + n(s.width) + ", \"height\": " + n(s.height) +
                     ", \"eye_rays_per_pixel\": " + perPixel(s.eyeRays) + ", \"threads\": " + n(s.threads) +
                     ", \"milliseconds\": {\"load\": " + ms(s.load) + ", \"build\": " + ms(s.build) +
                     ", \"trace\": " + ms(s.trace) + ", \"write\": " + ms(s.write) + ", \"total\": " + ms(total(s)) +
                     "}, \"rays\": {\"eye\": " + n(s.rays.eye) + ", \"gather\": " + n(s.rays.gather) +
                     ", \"shadow\": " + n(s.rays.shadow) + ", \"secondary\": " + n(s.rays.secondary) +
                     ", \"total\": " + n(s.rays.total()) + "}, \"million_rays_per_second\": " + rate(s);
  if (s.cache) {
    json += ", \"irradiance_cache\": {\"records\": " + n(s.rays.cacheRecords) + ", \"lookups\": " +
            n(s.rays.cacheLookups) + ", \"gathered_uncached\": " + n(s.rays.cacheMisses) + "}";
  }
  return json + ", \"peak_memory_bytes\": " + n(s.peakMemory) + "}\n";
}

}  // namespace rt
