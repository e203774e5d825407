#include "raytrace/render/ray_tree.hpp"

#include "raytrace/util/format.hpp"

namespace rt {

namespace {

const char* kindName(RayRecord::Kind kind) {
  switch (kind) {
    case RayRecord::Kind::Primary: return "Primary";
    case RayRecord::Kind::Reflection: return "Reflection";
    case RayRecord::Kind::Refraction: return "Refraction";
  }
  return "";
}

std::string ray(const glm::dvec3& origin, const glm::dvec3& dir) { return braces(origin) + " -> " + braces(dir); }

// One node and its subtree. `prefix` is the indentation of the node's branch in the decorated layout (always
// empty in the plain one). Labels are right-aligned to 16 characters (§a.3); the decorated layout marks the
// node with "o - ", continues its lines with "|   " and joins the children with "|\" and " \" (§a.9).
void printNode(std::ostream& out, const std::string& prefix, const RayRecord& r, bool decorated) {
  if (!decorated) out << prefix << "----\n";
  out << prefix << (decorated ? "o - " : "") << "  Iteration type: " << kindName(r.kind) << "\n";
  const std::string p = prefix + (decorated ? "|   " : "");
  out << p << "             Ray: " << ray(r.origin, r.dir) << "\n";
  if (r.hit) {
    out << p << "      Hit Object: (ID #" << r.objectId << " - " << r.objectType << ")\n"
        << p << "    Intersection: " << braces(r.point) << " at T = " << fixed4(r.t) << "\n"
        << p << "          Normal: " << braces(r.normal) << "\n"
        << p << "     Final Color: " << braces(r.color) << "\n"
        << p << "         Ambient: " << braces(r.ambient) << "\n"
        << p << "         Diffuse: " << braces(r.diffuse) << "\n"
        << p << "        Specular: " << braces(r.specular) << "\n"
        << p << "      Reflection: " << braces(r.reflection) << "\n"
        << p << "      Refraction: " << braces(r.refraction) << "\n"
        << p << "   Contributions: " << fixed4(r.local) << " Local, " << fixed4(r.reflect) << " Reflection, "
        << fixed4(r.transmit) << " Transmission\n";
    if (decorated) {
      for (size_t i = 0; i < r.shadows.size(); ++i) {
        const ShadowRecord& s = r.shadows[i];
        out << p << "   ShadowRay [" << i << "]: " << ray(s.origin, s.dir) << (s.occluded ? " (in shadow)" : "")
            << "\n";
      }
    }
  } else {
    out << p << "  No intersection.\n";
  }
  if (!r.extraInfo.empty()) {
    out << p << "      Extra Info:";
    for (const std::string& info : r.extraInfo) out << " " << info;
    out << "\n";
  }
  if (r.children.empty()) {
    if (decorated) out << prefix << "|----\n";
    out << prefix << "\n";
    return;
  }
  if (decorated) out << prefix << "|\n";
  for (size_t i = 0; i < r.children.size(); ++i) {
    const bool last = i + 1 == r.children.size();
    if (decorated) out << prefix << (last ? " \\" : "|\\") << "\n";
    printNode(out, prefix + (decorated ? (last ? "  " : "| ") : ""), r.children[i], decorated);
  }
}

}  // namespace

void printRayTrees(std::ostream& out, int x, int y, const std::string& color, const std::vector<RayRecord>& trees,
                   bool decorated, const std::vector<GatherSummary>& gathers) {
  out << "Pixel: [" << x << ", " << y << "] Color: " << color << "\n";
  for (const RayRecord& tree : trees) printNode(out, "", tree, decorated);
  for (size_t b = 0; b < gathers.size(); ++b) {
    const GatherSummary& g = gathers[b];
    out << "Gather bounce " << b + 1 << ": " << g.rays << (g.rays == 1 ? " ray" : " rays") << ", mean radiance "
        << braces(glm::dvec3(g.rays ? g.radiance / float(g.rays) : Color(0))) << "\n";
  }
  out << "\n" << std::string(80, '-') << "\n\n";
}

}  // namespace rt
