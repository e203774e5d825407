#include "raytrace/parse/povray/radiosity_reader.hpp"

#include <string>
#include <string_view>

#include "raytrace/util/error.hpp"

namespace rt::povray {

namespace {

// The number after the setting at i (i moves onto it), or a located error naming the setting.
double number(const Node& n, size_t& i) {
  const Item& word = n.items[i];
  const Value* v = valueAfter(n, i);
  if (!v || v->type != Value::Type::Float) {
    throw ParseError(word.loc, "radiosity's '" + std::string(word.word) + "' needs a number");
  }
  return v->v[0];
}

// A Bool setting: the value after it, or on when none follows (`always_sample` alone).
bool flag(const Node& n, size_t& i) {
  const Value* v = valueAfter(n, i);
  return !v || v->v[0] != 0;
}

// A count: a whole number from `least` to 10^7.
int whole(const Node& n, size_t& i, int least) {
  const Item& word = n.items[i];
  const double x = number(n, i);
  if (!(x >= least && x <= 1e7)) {
    throw ParseError(word.loc, "radiosity's '" + std::string(word.word) + "' must be from " + std::to_string(least) +
                                   " to 10000000");
  }
  return int(x);
}

// The optional second value of `count` and `nearest_count`, after a comma.
int second(const Node& n, size_t& i, int least) {
  if (i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Value) return whole(n, i, least);
  return 0;
}

}  // namespace

RadiosityDesc readRadiosity(const Node& n, ReadingContext& context) {
  RadiosityDesc r;
  for (size_t i = 0; i < n.items.size(); ++i) {
    const Item& it = n.items[i];
    if (it.kind != Item::Kind::Keyword) {
      context.refuse(it, "radiosity");
      continue;
    }
    const std::string_view w = it.word;
    if (w == "adc_bailout") {
      r.adcBailout = number(n, i);
    } else if (w == "always_sample") {
      r.alwaysSample = flag(n, i);
    } else if (w == "brightness") {
      r.brightness = number(n, i);
    } else if (w == "count") {
      r.count = whole(n, i, 1);
      r.countPool = second(n, i, 1);
    } else if (w == "error_bound") {
      r.errorBound = number(n, i);
    } else if (w == "gray_threshold") {
      r.grayThreshold = number(n, i);
    } else if (w == "low_error_factor") {
      r.lowErrorFactor = number(n, i);
    } else if (w == "max_sample") {
      r.maxSample = number(n, i);
    } else if (w == "maximum_reuse") {
      r.maximumReuse = number(n, i);
    } else if (w == "minimum_reuse") {
      r.minimumReuse = number(n, i);
    } else if (w == "nearest_count") {
      r.nearestCount = whole(n, i, 1);
      r.nearestCountPretrace = second(n, i, 1);
    } else if (w == "normal") {
      r.normal = flag(n, i);
    } else if (w == "media") {
      r.media = flag(n, i);
    } else if (w == "subsurface") {
      r.subsurface = flag(n, i);
    } else if (w == "pretrace_start") {
      r.pretraceStart = number(n, i);
    } else if (w == "pretrace_end") {
      r.pretraceEnd = number(n, i);
    } else if (w == "recursion_limit") {
      r.recursionLimit = whole(n, i, 1);
    } else {
      context.refuse(it.loc, w);
      valueAfter(n, i);
    }
  }
  return r;
}

}  // namespace rt::povray
