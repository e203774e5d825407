// raytrace_embree: the same rays through our Scene and through Embree 3, in millions of rays per second, and a
// check that both find the same things. bench/README.md describes the table; bench/embree.py runs it over the
// benchmark scenes.
//
//   raytrace_embree SCENE [--size 1280x960] [--runs 5] [--threads 1,2] [--quality high|medium] [--sphere robust|textbook]
//                   [--kinds "eye 1,mirror"] [--name NAME]

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include <time.h>

#include "embree_scene.hpp"
#include "ray_sets.hpp"
#include "raytrace/shapes/sphere.hpp"
#include "raytrace/shapes/triangle.hpp"
#include "raytrace/parse/scene_file.hpp"
#include "raytrace/util/parallel.hpp"
#include "raytrace/util/stopwatch.hpp"

namespace rt::bench {
namespace {

struct Options {
  std::string scene, name;
  int width = 1280, height = 960, runs = 5;
  std::vector<int> threads{1, 2};
  bool high = true;
  SphereMethod sphere = SphereMethod::Auto;  // the scene's own unless asked
  std::vector<std::string> kinds;            // the ray sets to trace; empty: all
  std::string embreeConfig;                  // more of Embree's device settings, such as its hierarchy's kind
};

// Rays per task handed to a thread, as many as in one of the renderer's 32×32 tiles.
constexpr size_t kChunkRays = 1024;
// Seed of the diffuse bounces' directions: the same rays on every run.
constexpr uint32_t kSeed = 473;
// Two answers agree when they name the same object (or none) and their t differ by at most this much relative
// to t (at least 1): the error budget of a hit (docs/reference/stability.md §1.1). Embree's sphere test in
// float is off by up to about 1e-4 relative at grazing angles.
constexpr double kTolerance = 1e-3;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

double threadSeconds() {
  timespec now;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

// Runs task(first, n) for each packet (or single ray) of the set, in chunks of about kChunkRays rays handed to
// the threads, and returns the processor time the chunks took on their threads, summed. The machine is
// shared: wall time would count the time other processes had the cores, processor time only the work.
template <class T, class Task> double forChunks(const RaySet<T>& set, int threads, const Task& task) {
  std::vector<uint32_t> bounds;
  if (set.packets) {
    for (size_t k = 0; k < set.start.size(); k += kChunkRays / Bvh<T>::kPacket) bounds.push_back(set.start[k]);
  } else {
    for (size_t r = 0; r < set.rays.size(); r += kChunkRays) bounds.push_back(uint32_t(r));
  }
  bounds.push_back(uint32_t(set.rays.size()));
  const std::vector<uint32_t>& packetStart = set.start;
  std::vector<double> seconds(bounds.size() - 1);
  parallelFor(int(bounds.size()) - 1, threads, [&](int c) {
    const double start = threadSeconds();
    const uint32_t first = bounds[size_t(c)], last = bounds[size_t(c) + 1];
    if (!set.packets) {
      for (uint32_t r = first; r < last; ++r) task(r, 1);
    } else {
      auto k = std::lower_bound(packetStart.begin(), packetStart.end(), first);
      for (; k + 1 != packetStart.end() && *k < last; ++k) task(*k, int(k[1] - k[0]));
    }
    seconds[size_t(c)] = threadSeconds() - start;
  });
  double total = 0;
  for (double s : seconds) total += s;
  return total;
}

template <class T> double traceOurs(const Scene<T>& scene, const RaySet<T>& set, int threads, std::vector<Answer>& out) {
  // A shadow cache per light and thread, as each of the renderer's tile tracers has; only ever a hint.
  const size_t lights = scene.lights().size();
  return forChunks(set, threads, [&](uint32_t first, int n) {
    thread_local std::vector<const Object<T>*> lastBlocker;
    if (lastBlocker.size() < lights) lastBlocker.resize(lights);
    const Ray<T>* rays = &set.rays[first];
    Answer* answers = &out[first];
    if (set.anyHit) {
      bool blocked[Bvh<T>::kPacket];
      const Object<T>** cache = &lastBlocker[size_t(std::max(0, set.light[first]))];
      if (set.packets) {
        scene.occluded(rays, &set.ranges[first], n, blocked, cache);
      } else {
        blocked[0] = scene.occluded(rays[0], set.ranges[first], cache);
      }
      for (int i = 0; i < n; ++i) answers[i] = {blocked[i], 0};
      return;
    }
    const auto answer = [](const std::optional<Hit<T>>& hit) {
      return hit ? Answer{hit->object->id(), float(hit->t)} : Answer{};
    };
    // A single ray's one answer only: a packet's array of records would cost a single ray a tenth of its time.
    if (!set.packets) {
      answers[0] = answer(scene.closestHit(rays[0], set.ranges[first]));
      return;
    }
    std::optional<Hit<T>> hits[Bvh<T>::kPacket];
    scene.closestHits(rays, n, set.ranges[first], hits);
    for (int i = 0; i < n; ++i) answers[i] = answer(hits[i]);
  });
}

template <class T>
double traceEmbree(const EmbreeScene<T>& embree, const RaySet<T>& set, int threads, std::vector<Answer>& out) {
  return forChunks(set, threads, [&](uint32_t first, int n) {
    if (set.anyHit) {
      bool blocked[Bvh<T>::kPacket];
      embree.occluded(&set.rays[first], &set.ranges[first], n, set.packets, blocked);
      for (int i = 0; i < n; ++i) out[first + size_t(i)] = {blocked[i], 0};
    } else {
      embree.closest(&set.rays[first], &set.ranges[first], n, set.packets, &out[first]);
    }
  });
}

// Where object `id` meets the ray in double precision (the robust sphere formula), to tell which answer is
// right; -1 for a miss or a shape without a reference here.
template <class T> double referenceT(const SceneDesc& desc, int id, const Ray<T>& ray, Interval<T> range) {
  if (id < 1) return -1;
  const ObjectDesc& o = desc.objects[size_t(id - 1)];
  const Ray<double> r{glm::dvec3(ray.origin), glm::dvec3(ray.dir)};
  const Interval<double> within{double(range.min), double(range.max)};
  std::optional<Hit<double>> hit;
  if (const auto* s = std::get_if<SphereDesc>(&o.shape)) {
    hit = Sphere<double>(s->center, s->radius, SphereMethod::Robust, o.material, id).intersect(r, within);
  } else if (const auto* t = std::get_if<TriangleDesc>(&o.shape)) {
    hit = Triangle<double>(t->a, t->b, t->c, o.material, id).intersect(r, within);
  }
  return hit ? hit->t : -1;
}

// What testing every object in turn with our own shape tests answers: the hierarchy's answer must be this.
template <class T> Answer scanned(const Scene<T>& scene, const Ray<T>& ray, Interval<T> range, bool anyHit) {
  Answer best;
  for (const auto& object : scene.objects()) {
    if (const auto hit = object->intersect(ray, range)) {
      if (anyHit) return {1, 0};
      best = {object->id(), float(hit->t)}, range.max = hit->t;
    }
  }
  return best;
}

struct Agreement {
  size_t rays = 0, differ = 0, unexplained = 0;
};

// Rays whose answers differ beyond kTolerance, ties aside: two objects hit at the same t (triangles meeting at
// an edge) are both right, and Embree need not pick the one first in the file. A difference is explained by
// the shapes' arithmetic when testing every object in turn with our own shape tests answers what our
// hierarchy answered: the float tests of a silhouette differ (the course tier's textbook sphere formula most
// of all). Any other difference is the hierarchy's fault.
template <class T>
Agreement agreement(const Scene<T>& scene, const RaySet<T>& set, const std::vector<Answer>& ours,
                    const std::vector<Answer>& embree, const std::string& name) {
  Agreement result;
  result.rays = set.rays.size();
  for (size_t r = 0; r < set.rays.size(); ++r) {
    const Answer &a = ours[r], &b = embree[r];
    const auto near = [&](double t) { return std::abs(t - double(a.t)) <= kTolerance * std::max(1.0, double(a.t)); };
    if (a.object == b.object && (set.anyHit || !a.object || near(b.t))) continue;
    double mine = -1;  // Embree's object as our own test sees it
    if (b.object) {
      if (const auto hit = scene.objects()[size_t(b.object - 1)]->intersect(set.rays[r], set.ranges[r])) mine = hit->t;
    }
    if (!set.anyHit && a.object && mine >= 0 && near(b.t) && near(mine)) continue;
    ++result.differ;
    const Answer scan = scanned(scene, set.rays[r], set.ranges[r], set.anyHit);
    const bool explained = scan.object == a.object && (set.anyHit || !a.object || near(scan.t));
    if (!explained) ++result.unexplained;
    if (result.differ <= 3 || (!explained && result.unexplained <= 3)) {
      const SceneDesc& desc = scene.desc();
      std::printf("  disagreement %s %s ray %zu (%s): ours object %d t %.9g, Embree object %d t %.9g; in double "
                  "precision %d is hit at %.9g, %d at %.9g (-1: missed or not a sphere/triangle); our test of "
                  "%d: %.9g\n",
                  name.c_str(), set.kind.c_str(), r, explained ? "the shapes' arithmetic" : "NOT EXPLAINED",
                  a.object, double(a.t), b.object, double(b.t), a.object,
                  referenceT(desc, a.object, set.rays[r], set.ranges[r]), b.object,
                  referenceT(desc, b.object, set.rays[r], set.ranges[r]), b.object, mine);
    }
  }
  return result;
}

template <class T> int run(const Options& options, const SceneDesc& desc, const Arithmetic& arithmetic) {
  const int most = *std::max_element(options.threads.begin(), options.threads.end());
  const Scene<T> scene(desc, arithmetic, Hierarchy::Auto, most);
  const Camera<T> camera(desc.camera, options.width, options.height);
  std::vector<RaySet<T>> sets = makeRaySets(scene, camera, kSeed);
  if (!options.kinds.empty()) {
    sets.erase(std::remove_if(sets.begin(), sets.end(), [&](const RaySet<T>& set) {
      return std::find(options.kinds.begin(), options.kinds.end(), set.kind) == options.kinds.end();
    }), sets.end());
  }
  std::vector<const Object<T>*> bounded;
  for (const auto& o : scene.objects()) {
    if (o->bounds()) bounded.push_back(o.get());
  }
  std::printf("# %s: %zu objects (%zu bounded), %s, %dx%d, hierarchy %s; rays:", options.name.c_str(),
              scene.objects().size(), bounded.size(), sizeof(T) == 4 ? "float" : "double", options.width,
              options.height, scene.hierarchy() ? "yes" : "no (scanned)");
  for (const RaySet<T>& s : sets) std::printf(" %s %zu", s.kind.c_str(), s.rays.size());
  std::printf("\n");

  Agreement all;
  for (int threads : options.threads) {
    std::vector<double> ourBuild, embreeBuild;
    std::unique_ptr<EmbreeScene<T>> embree;
    for (int r = 0; r < std::max(1, options.runs / 2); ++r) {
      Stopwatch watch;
      { const Bvh<T> bvh(bounded, threads); }
      ourBuild.push_back(watch.lap());
      embree.reset();
      watch.lap();
      embree = std::make_unique<EmbreeScene<T>>(scene, threads, options.high, options.embreeConfig);
      embreeBuild.push_back(watch.lap());
    }
    const double ours = median(ourBuild) * 1e3, theirs = median(embreeBuild) * 1e3;
    std::printf("| %s | build (ms) | %d | %.1f | %.1f | %.2f |\n", options.name.c_str(), threads, ours, theirs,
                theirs / ours);
    for (const RaySet<T>& set : sets) {
      std::vector<Answer> a(set.rays.size()), b(set.rays.size());
      std::vector<double> oursTime, embreeTime;
      for (int r = 0; r < options.runs; ++r) {
        // Alternate which goes first, so that neither always runs on a cache the other warmed.
        for (int side = 0; side < 2; ++side) {
          if ((side + r) % 2 == 0) {
            oursTime.push_back(traceOurs(scene, set, threads, a) / threads);
          } else {
            embreeTime.push_back(traceEmbree(*embree, set, threads, b) / threads);
          }
        }
      }
      const double n = double(set.rays.size()) * 1e-6;
      const double mOurs = n / median(oursTime), mEmbree = n / median(embreeTime);
      std::printf("| %s | %s | %d | %.2f | %.2f | %.2f |\n", options.name.c_str(), set.kind.c_str(), threads, mOurs,
                  mEmbree, mOurs / mEmbree);
      if (threads == options.threads.front()) {
        const Agreement one = agreement(scene, set, a, b, options.name);
        all.rays += one.rays, all.differ += one.differ, all.unexplained += one.unexplained;
      }
    }
    std::fflush(stdout);
  }
  std::printf("# agreement %s: %zu of %zu rays agree (%.4f %%; same object, |dt| <= %g max(1, t)); of the %zu "
              "others, %zu not explained by the shapes' arithmetic\n",
              options.name.c_str(), all.rays - all.differ, all.rays,
              100.0 * double(all.rays - all.differ) / double(all.rays), kTolerance, all.differ, all.unexplained);
  return all.unexplained == 0 && double(all.rays - all.differ) >= 0.9999 * double(all.rays) ? 0 : 2;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--size") {
      const std::string v = value();
      if (std::sscanf(v.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 1 || o.height < 1) {
        throw std::runtime_error("--size wants WxH, not " + v);
      }
    } else if (a == "--runs") {
      o.runs = std::max(1, std::atoi(value().c_str()));
    } else if (a == "--threads") {
      o.threads.clear();
      const std::string v = value();
      for (size_t p = 0; p < v.size();) {
        const size_t comma = std::min(v.find(',', p), v.size());
        o.threads.push_back(std::max(1, std::atoi(v.substr(p, comma - p).c_str())));
        p = comma + 1;
      }
      if (o.threads.empty()) throw std::runtime_error("--threads wants a list such as 1,2");
    } else if (a == "--sphere") {
      const std::string v = value();
      if (v != "robust" && v != "textbook") throw std::runtime_error("--sphere is robust or textbook, not " + v);
      o.sphere = v == "robust" ? SphereMethod::Robust : SphereMethod::Textbook;
    } else if (a == "--quality") {
      const std::string v = value();
      if (v != "high" && v != "medium") throw std::runtime_error("--quality is high or medium, not " + v);
      o.high = v == "high";
    } else if (a == "--kinds") {
      const std::string v = value();
      for (size_t p = 0; p < v.size();) {
        const size_t comma = std::min(v.find(',', p), v.size());
        o.kinds.push_back(v.substr(p, comma - p));
        p = comma + 1;
      }
    } else if (a == "--embree-config") {
      o.embreeConfig = value();
    } else if (a == "--name") {
      o.name = value();
    } else if (o.scene.empty() && a[0] != '-') {
      o.scene = a;
    } else {
      throw std::runtime_error("unknown argument " + a);
    }
  }
  if (o.scene.empty()) {
    throw std::runtime_error("usage: raytrace_embree SCENE [--size WxH] [--runs N] [--threads 1,2] "
                             "[--quality high|medium] [--sphere robust|textbook] [--kinds K1,K2] [--name NAME] "
                             "[--embree-config SETTINGS]");
  }
  if (o.name.empty()) {
    const size_t slash = o.scene.find_last_of('/') + 1, dot = o.scene.find_last_of('.');
    o.name = o.scene.substr(slash, dot == std::string::npos || dot < slash ? std::string::npos : dot - slash);
  }
  return o;
}

}  // namespace
}  // namespace rt::bench

int main(int argc, char** argv) {
  try {
    const rt::bench::Options options = rt::bench::parse(argc, argv);
    const rt::SceneDesc desc = rt::loadScene(options.scene, 2);
    rt::Arithmetic requested;
    requested.sphere = options.sphere;
    const rt::Arithmetic arithmetic = rt::chooseArithmetic(desc, requested);
    return rt::withPrecision(arithmetic.tier, [&](auto tag) {
      return rt::bench::run<decltype(tag)>(options, desc, arithmetic);
    });
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raytrace_embree: %s\n", e.what());
    return 1;
  }
}
