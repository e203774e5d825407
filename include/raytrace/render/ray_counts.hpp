// The rays a render traced, by kind: what --stats reports beside the times.
#pragma once

#include <cstdint>

namespace rt {

// How many rays of each kind a render traced (--stats).
struct RayCounts {
  uint64_t eye = 0, gather = 0, shadow = 0, secondary = 0;  // secondary: reflection and refraction
  // --gi-cache: records made, lookups, and lookups no record covered that gathered without storing.
  uint64_t cacheRecords = 0, cacheLookups = 0, cacheMisses = 0;
  uint64_t total() const { return eye + gather + shadow + secondary; }
  RayCounts& operator+=(const RayCounts& o) {
    eye += o.eye, gather += o.gather, shadow += o.shadow, secondary += o.secondary;
    cacheRecords += o.cacheRecords, cacheLookups += o.cacheLookups, cacheMisses += o.cacheMisses;
    return *this;
  }
};

}  // namespace rt
