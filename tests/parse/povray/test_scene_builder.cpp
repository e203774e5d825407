// The POV-Ray scene builder: what each statement of a scene becomes in the scene description.
#include <catch2/catch.hpp>

#include <iostream>
#include <sstream>
#include <string>

#include "raytrace/parse/povray/scene_builder.hpp"

namespace rt::povray {
namespace {

SceneDesc scene(const std::string& body) {
  return parsePovRay("#version 3.7;\n#include \"colors.inc\"\n" + body, "scene.pov", PovRayOptions{{}, 320, 240, false});
}

std::string failure(const std::string& body) {
  try {
    scene(body);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST_CASE("povray scene: a union's children become objects of the scene under the union's transforms and texture",
          "[povray]") {
  const SceneDesc s = scene(R"(
#declare Pair = union {
  sphere { 0, 1 translate y }
  box { 0, 1 pigment { Red } }
  pigment { Green }
  scale 2
}
object { Pair translate x }
object { Pair }
)");
  REQUIRE(s.objects.size() == 4);
  CHECK(std::get<SphereDesc>(s.objects[0].shape).radius == 1);
  CHECK(s.objects[0].material.pigment == Color(0, 1, 0));  // the union's
  CHECK(s.objects[1].material.pigment == Color(1, 0, 0));  // its own
  // The child's own transforms, then the union's, then the object's.
  REQUIRE(s.objects[0].transforms.size() == 3);
  CHECK(s.objects[0].transforms[0].v == glm::dvec3(0, 1, 0));
  CHECK(s.objects[0].transforms[1].v == glm::dvec3(2));
  CHECK(s.objects[0].transforms[2].v == glm::dvec3(1, 0, 0));
  CHECK(s.objects[2].transforms.size() == 2);
  CHECK(s.objects[3].transforms.size() == 1);
}

TEST_CASE("povray scene: hollow goes to a CSG's parts that do not say otherwise", "[povray]") {
  const SceneDesc s = scene(R"(
sphere { 0, 1 }
sphere { 0, 1 hollow }
sphere { 0, 1 hollow off }
union { sphere { 0, 1 } sphere { 0, 1 hollow off } hollow }
difference { sphere { 0, 1 hollow } sphere { 0, 1 } pigment { Red } }
)");
  REQUIRE(s.objects.size() == 6);
  CHECK_FALSE(s.objects[0].material.extras->hollow);  // solid by default (the manual, "Empty and Solid Objects")
  CHECK(s.objects[1].material.extras->hollow);
  CHECK_FALSE(s.objects[2].material.extras->hollow);
  CHECK(s.objects[3].material.extras->hollow);
  CHECK_FALSE(s.objects[4].material.extras->hollow);
  const auto& diff = std::get<CsgDesc>(s.objects[5].shape);
  CHECK(diff.children[0].material.extras->hollow);
  CHECK_FALSE(diff.children[1].material.extras->hollow);
}

TEST_CASE("povray scene: intersection, difference and merge stay groups, their children textured as POV-Ray does",
          "[povray]") {
  const SceneDesc s = scene(R"(
difference {
  box { -1, 1 }
  union { sphere { 0, 1.2 pigment { Blue } } cylinder { -2*x, 2*x, 0.5 } }
  pigment { Yellow }
  rotate 90*y
}
merge { sphere { 0, 1 } sphere { x, 1 } }
)");
  REQUIRE(s.objects.size() == 2);
  const auto& diff = std::get<CsgDesc>(s.objects[0].shape);
  CHECK(diff.op == CsgOp::Difference);
  REQUIRE(diff.children.size() == 2);
  CHECK(diff.children[0].material.pigment == Color(1, 1, 0));
  const auto& inner = std::get<CsgDesc>(diff.children[1].shape);
  CHECK(inner.op == CsgOp::Union);  // inside a difference a union is a solid, not split
  CHECK(inner.children[0].material.pigment == Color(0, 0, 1));
  CHECK(inner.children[1].material.pigment == Color(1, 1, 0));
  CHECK(s.objects[0].transforms.size() == 1);
  CHECK(std::get<CsgDesc>(s.objects[1].shape).op == CsgOp::Merge);
  CHECK(s.objects[1].material.pigment == Color(0));  // POV-Ray's default texture is black
}

TEST_CASE("povray scene: light sources inside objects move with them; a union may hold lights alone", "[povray]") {
  const SceneDesc s = scene(R"(
union { light_source { <1, 0, 0> White } light_source { <0, 1, 0> Red } translate 10*z }
#declare Lamp = union { sphere { 0, 0.1 } light_source { 0 White } translate y }
object { Lamp translate x }
)");
  REQUIRE(s.lights.size() == 3);
  CHECK(s.lights[0].position == glm::dvec3(1, 0, 10));
  CHECK(s.lights[1].position == glm::dvec3(0, 1, 10));
  CHECK(s.lights[1].color == Color(1, 0, 0));
  CHECK(s.lights[2].position == glm::dvec3(1, 1, 0));
  REQUIRE(s.objects.size() == 1);
}

TEST_CASE("povray scene: spotlights, fading and shadowless lights; the cone moves with the light", "[povray]") {
  const SceneDesc s = scene(R"(
light_source { <0, 10, 0> White point_at <0, 0, 1> radius 10 spotlight translate x }
light_source { <0, 10, 0> White point_at <0, 0, 1> fade_distance 3 fade_power 1 shadowless }
#declare Lamp = light_source { 0, Red spotlight falloff 20 tightness 5 }
light_source { Lamp rotate 90*z }
)");
  REQUIRE(s.lights.size() == 3);
  REQUIRE(s.lights[0].spot);
  CHECK(s.lights[0].spot->pointAt == glm::dvec3(1, 0, 1));
  CHECK(s.lights[0].spot->radius == 10);
  CHECK(s.lights[0].spot->falloff == 45);
  CHECK_FALSE(s.lights[1].spot);  // point_at alone makes no spotlight
  CHECK(s.lights[1].shadowless);
  CHECK(s.lights[1].fadeDistance == 3);
  CHECK(s.lights[2].spot->tightness == 5);
  CHECK(s.lights[2].color == Color(1, 0, 0));
}

TEST_CASE("povray scene: area, parallel and cylinder lights; looks_like draws its object at the light", "[povray]") {
  const SceneDesc s = scene(R"(
light_source { <0, 10, 0> White area_light 2*x, 2*z, 5, 3 adaptive 1 jitter circular orient rotate 90*y }
light_source { <0, 10, 0> White parallel point_at <0, 0, 1> translate x }
light_source { <0, 10, 0> White cylinder point_at 0 radius 2 }
light_source { <0, 5, 0> White looks_like { sphere { 0, 1 } } translate x }
)");
  REQUIRE(s.lights.size() == 4);
  REQUIRE(s.lights[0].area);
  const AreaDesc& a = *s.lights[0].area;
  CHECK(a.axis1.x == Approx(0).margin(1e-12));  // turned with the light: 2x becomes −2z
  CHECK(a.axis1.z == Approx(-2));
  CHECK(a.axis2.x == Approx(2));
  CHECK(a.size1 == 5);
  CHECK(a.size2 == 3);
  CHECK(a.adaptive == 1);
  CHECK((a.jitter && a.circular && a.orient));
  CHECK_FALSE(a.illumination);
  CHECK_FALSE(s.lights[1].area);
  REQUIRE(s.lights[1].parallelTo);
  CHECK(*s.lights[1].parallelTo == glm::dvec3(1, 0, 1));
  CHECK_FALSE(s.lights[1].spot);
  REQUIRE(s.lights[2].spot);
  CHECK(s.lights[2].spot->kind == lightKindNamed("cylinder"));
  CHECK(s.lights[2].spot->radius == 2);
  CHECK(s.lights[2].spot->falloff == 1);  // a cylinder light's default
  REQUIRE(s.objects.size() == 1);  // the looks_like sphere, about the light and moved with it, casting no shadow
  CHECK(s.objects[0].noShadow);
  CHECK(glm::dvec3(s.objects[0].worldFromObject() * glm::dvec4(0, 0, 0, 1)) == glm::dvec3(1, 5, 0));
  CHECK(s.lights[3].position == glm::dvec3(1, 5, 0));
}

TEST_CASE("povray scene: quick_color, for a preview without textures, leaves the colour as it is, in any "
          "spelling", "[povray]") {
  const SceneDesc s = scene(R"(
sphere { 0, 1 pigment { color red 1 green 0.5 quick_colour red 0.7 green 0.7 blue 1 } }
sphere { 0, 1 pigment { rgb <0, 0, 1> quick_color rgb <1, 0, 0> } }
)");
  REQUIRE(s.objects.size() == 2);
  CHECK(s.objects[0].material.pigment == Color(1, 0.5f, 0));
  CHECK(s.objects[1].material.pigment == Color(0, 0, 1));
}

TEST_CASE("povray scene: a light inside an object moves with it, and its looks_like object too", "[povray]") {
  const SceneDesc s = scene(R"(
#declare Lamp = light_source { 0, White looks_like { sphere { 0, 1 } } translate y }
object { Lamp translate x }
union { sphere { 0, 1 } light_source { 0, White looks_like { sphere { 0, 0.5 } } } translate z }
)");
  REQUIRE(s.lights.size() == 2);
  CHECK(s.lights[0].position == glm::dvec3(1, 1, 0));
  CHECK(s.lights[1].position == glm::dvec3(0, 0, 1));
  REQUIRE(s.objects.size() == 3);  // the lamp's looks_like object, the union, and the looks_like object of its light
  const auto centre = [](const ObjectDesc& o) { return glm::dvec3(o.worldFromObject() * glm::dvec4(0, 0, 0, 1)); };
  const ObjectDesc& lampLook = s.objects[0];
  const ObjectDesc& unionLook = s.objects[2];
  CHECK(lampLook.noShadow);
  CHECK(centre(lampLook) == glm::dvec3(1, 1, 0));
  CHECK(unionLook.noShadow);
  CHECK(centre(unionLook) == glm::dvec3(0, 0, 1));
}

TEST_CASE("povray scene: an area light's modifiers before area_light; a point light's are ignored, as POV-Ray "
          "does, but circular, which needs a grid", "[povray]") {
  const SceneDesc s = scene(R"(
light_source { 0, White jitter adaptive 2 area_light x, z, 3, 3 }
light_source { 0, White jitter adaptive 1 orient }
)");
  REQUIRE(s.lights.size() == 2);
  REQUIRE(s.lights[0].area);
  CHECK(s.lights[0].area->jitter);
  CHECK(s.lights[0].area->adaptive == 2);
  CHECK_FALSE(s.lights[1].area);
  CHECK(failure("light_source { 0, White circular }\n") ==
        "scene.pov:3:25: error: 'circular' needs an area_light of more than one point along each axis");
  CHECK(failure("light_source { 0, White area_light x, z, 1, 4 circular }\n") ==
        "scene.pov:3:47: error: 'circular' needs an area_light of more than one point along each axis");
}

TEST_CASE("povray scene: a fog's turbulence and its modifiers; the scene's noise_generator", "[povray]") {
  const SceneDesc d = scene(
      "fog { fog_type 2 distance 5 rgb 1 turbulence <0.2, 0.3, 0.4> turb_depth 0.7 octaves 12 omega 0.4 lambda 3 }\n"
      "fog { distance 5 rgb 1 turbulence 0.5 }\n"
      "global_settings { noise_generator 1 }\n");
  REQUIRE(d.fogs.size() == 2);
  const Fog& f = d.fogs[0];
  CHECK(f.turbulence.amount == glm::dvec3(0.2, 0.3, 0.4));
  CHECK(f.turbDepth == 0.7);
  CHECK(f.turbulence.octaves == 10);  // POV-Ray's limit
  CHECK(f.turbulence.omega == 0.4f);
  CHECK(f.turbulence.lambda == 3.0f);
  CHECK(f.noise.get() == NoiseGenerator::Original);  // set after the fog, read when drawn
  CHECK(d.fogs[1].turbulence.amount == glm::dvec3(0.5));
  CHECK(d.fogs[1].turbDepth == 0.5);
  CHECK(failure("fog { distance 5 rgb 1 turbulence 1 warp { repeat x } }\n") ==
        "scene.pov:3:37: error: 'warp' is not supported yet");
  CHECK(scene("fog { distance 5 rgb 1 turbulence 0.5 }\nglobal_settings { noise_generator 3.5 }\n")
            .fogs[0]
            .noise.get() == NoiseGenerator::Perlin);  // POV-Ray drops the fraction
  CHECK(failure("global_settings { noise_generator 4 }\n") ==
        "scene.pov:3:19: error: noise_generator in global_settings must be 1, 2 or 3, found 4");
}

TEST_CASE("povray scene: scene-level media are read as an interior's, in order", "[povray][media]") {
  const SceneDesc s = scene("media { emission 0.5 samples 4 } media { absorption <1, 0, 0.5> }\n");
  REQUIRE(s.media.size() == 2);
  CHECK(s.media[0].emission == Color(0.5f));
  CHECK(s.media[0].samples == 4);
  CHECK(s.media[1].absorption == Color(1, 0, 0.5f));
  CHECK(s.objects.empty());
}

TEST_CASE("povray scene: an interior's media, its densities and scattering; other methods are refused", "[povray][media]") {
  const SceneDesc s = scene(R"(
box { -1, 1 hollow pigment { rgbt 1 }
      interior { media { absorption <0.5, 1, 0> emission 0.2 intervals 3 samples 4, 8 method 3 } } }
sphere { x * 10, 1 }
)");
  const SurfaceExtras& e = *s.objects[0].material.extras;
  REQUIRE(e.media.size() == 1);
  CHECK(e.media[0].absorption == Color(0.5f, 1, 0));
  CHECK(e.media[0].emission == Color(0.2f));
  CHECK(e.media[0].samples == 4);
  CHECK(s.objects[1].material.extras->media.empty());
  // A declared medium, modified where it is used.
  const SceneDesc d = scene("#declare M = media { emission 0.5 samples 3 }\n"
                            "sphere { 0, 1 interior { media { M absorption 2 } } }\n");
  const Media& m = d.objects[0].material.extras->media.at(0);
  CHECK(m.emission == Color(0.5f));
  CHECK(m.absorption == Color(2));
  CHECK(m.samples == 3);
  // Densities: white by default; a pattern without a map ramps from black to white; density_map as pigment_map.
  const SceneDesc ds = scene("sphere { 0, 1 interior { media { emission 1 intervals 2 density { } density { rgb 0.5 }\n"
                             "  density { gradient x } density { gradient y density_map { [0 density { rgb 0.2 }] [1 rgb 1] } } } } }\n");
  const Media& dm = ds.objects[0].material.extras->media.at(0);
  CHECK(dm.intervals == 2);
  REQUIRE(dm.densities.size() == 4);
  CHECK(dm.densities[0]->at(glm::dvec3(0.3)).rgb == Color(1));
  CHECK(dm.densities[1]->at(glm::dvec3(0.3)).rgb == Color(0.5f));
  CHECK(dm.densities[2]->at(glm::dvec3(0.25, 0, 0)).rgb == Color(0.25f));
  CHECK(dm.densities[3]->at(glm::dvec3(0, 0.5, 0)).rgb == Color(0.6f));
  CHECK(failure("box { -1, 1 interior { media { emission 1 density { spherical warp { cubic dist_exp 1 } } } } }\n") ==
        "scene.pov:3:76: error: 'dist_exp' is not supported yet");
  // Scattering, its defaults, and method 3's adaptive sampling.
  const SceneDesc sc = scene("sphere { 0, 1 interior { media { scattering { 5, rgb <0.1, 0.2, 0.3> eccentricity 0.4 }\n"
                             "  aa_level 5 aa_threshold 0.2 } } }\n"
                             "sphere { x * 10, 1 interior { media { scattering { 2, 0.5 extinction 0.25 } } } }\n"
                             "light_source { 0, 1 media_interaction off }\n");
  const Media& s5 = sc.objects[0].material.extras->media.at(0);
  REQUIRE(s5.scattering);
  CHECK(s5.scattering->type == 5);
  CHECK(s5.scattering->color == Color(0.1f, 0.2f, 0.3f));
  CHECK(s5.scattering->eccentricity == 0.4);
  CHECK(s5.scattering->extinction == 1);
  CHECK(s5.aaLevel == 5);
  CHECK(s5.aaThreshold == 0.2);
  const Media& s2 = sc.objects[1].material.extras->media.at(0);
  CHECK(s2.scattering->type == 2);
  CHECK(s2.scattering->eccentricity == 0);
  CHECK(s2.scattering->extinction == 0.25);
  CHECK(s2.aaLevel == 3);
  CHECK(s2.aaThreshold == 0.1);
  CHECK_FALSE(sc.lights[0].mediaInteraction);
  CHECK(failure("box { -1, 1 interior { media { scattering { 6, 0.5 } } } }\n") ==
        "scene.pov:3:45: error: 'scattering' needs a type from 1 to 5");
  CHECK(failure("box { -1, 1 interior { media { scattering { 1 } } } }\n") ==
        "scene.pov:3:32: error: 'scattering' needs a type and a colour");
  CHECK(failure("box { -1, 1 interior { media { emission 1 method 2 } } }\n") ==
        "scene.pov:3:43: error: 'media method other than 3' is not supported yet");
  // Several media in one interior, in order (the manual, "Multiple Media"), and a declared interior's.
  const SceneDesc two = scene("#declare I = interior { media { emission 1 } }\n"
                              "box { -1, 1 interior { media { emission 0.5 } media { absorption 1 } } }\n"
                              "box { -1, 1 interior { I media { absorption 2 } } }\n");
  const std::vector<Media>& both = two.objects[0].material.extras->media;
  REQUIRE(both.size() == 2);
  CHECK(both[0].emission == Color(0.5f));
  CHECK(both[1].absorption == Color(1));
  const std::vector<Media>& added = two.objects[1].material.extras->media;
  REQUIRE(added.size() == 2);
  CHECK(added[0].emission == Color(1));
  CHECK(added[1].absorption == Color(2));
  const SceneDesc dimmed = scene("light_source { 0, 1 media_attenuation on } light_source { 0, 1 media_attenuation }\n"
                                 "light_source { 0, 1 media_attenuation off } light_source { 0, 1 }\n");
  CHECK(dimmed.lights[0].mediaAttenuation);
  CHECK(dimmed.lights[1].mediaAttenuation);
  CHECK_FALSE(dimmed.lights[2].mediaAttenuation);
  CHECK_FALSE(dimmed.lights[3].mediaAttenuation);
  CHECK(failure("media { emission 1 method 1 }\n") == "scene.pov:3:20: error: 'media method other than 3' is not supported yet");
  // An object inside a medium, or a plane across it, is drawn (POV-Ray's rule on hollow objects).
  CHECK(failure("sphere { 0, 1 hollow interior { media { emission 1 } } scale 3 }\nsphere { x * 3.5, 1 }\n"
                "plane { y, 2 translate -y }\n") == "no error");
  CHECK(failure("box { -1, 1 interior { media { samples 0 } } }\n") ==
        "scene.pov:3:32: error: 'samples' needs at least 1");
}

TEST_CASE("povray scene: area_illumination, alone or on, before or after the grid; off; copied with the light",
          "[povray]") {
  const SceneDesc s = scene(R"(
#declare L = light_source { 0, White area_illumination area_light x, z, 2, 2 }
light_source { 0, White area_light x, z, 2, 2 area_illumination }
light_source { 0, White area_light x, z, 2, 2 area_illumination on area_illumination off }
light_source { L }
light_source { L area_illumination 0 }
light_source { 0, White area_illumination }
)");
  REQUIRE(s.lights.size() == 5);
  CHECK(s.lights[0].area->illumination);
  CHECK_FALSE(s.lights[1].area->illumination);
  CHECK(s.lights[2].area->illumination);
  CHECK_FALSE(s.lights[3].area->illumination);
  CHECK_FALSE(s.lights[4].area);  // one point lights the same either way
}

TEST_CASE("povray scene: light modifiers that are not drawn yet are refused where they are written", "[povray]") {
  CHECK(failure("light_source { 0, White cylinder tightness 3 }\n") ==
        "scene.pov:3:34: error: 'a cylinder light's tightness' is not supported yet");
  CHECK(failure("light_source { 0, White area_light x, z, 2 }\n") ==
        "scene.pov:3:25: error: 'area_light' needs two axes and two sizes");
  CHECK(failure("union { sphere { 0, 1 } light_source { 0, White projected_through { sphere { 0, 1 } } } }\n") ==
        "scene.pov:3:49: error: 'projected_through in a light inside an object' is not supported yet");
  CHECK(failure("light_source { 0, White projected_through { sphere { 0, 1 } } translate x }\n") ==
        "scene.pov:3:1: error: 'projected_through in a light with transforms' is not supported yet");
  CHECK(failure("light_source { 0, White projected_through { } }\n") ==
        "scene.pov:3:25: error: projected_through needs an object");
  CHECK(failure("light_source { 0, White projected_through { sphere { 0, 1 } box { 0, 1 } } }\n") ==
        "scene.pov:3:61: error: projected_through takes one object");
}

TEST_CASE("povray scene: a camera's normal is kept with the camera; a mesh_camera's is refused", "[povray]") {
  const SceneDesc s = scene("camera { location -5*z look_at 0 normal { bumps 0.4 scale 0.1 } }\n");
  REQUIRE(s.camera.normal);
  CHECK(s.camera.normal->amount == 0.4);
  CHECK(failure("camera { mesh_camera { 1 0 mesh { triangle { 0, x, y } } } normal { bumps 0.4 } }\n") ==
        "scene.pov:3:1: error: 'a mesh_camera's normal' is not supported yet");
}

TEST_CASE("povray scene: a light's projected_through object is kept with the light and not drawn", "[povray]") {
  const SceneDesc s = scene(R"(
#declare Window = sphere { <0, 3, 0>, 1 pigment { rgb 1 } };
light_source { <0, 6, 0> White projected_through { Window } }
)");
  REQUIRE(s.lights.size() == 1);
  REQUIRE(s.projectedThrough.size() == 1);
  REQUIRE(s.projectedThrough[0]);
  CHECK(std::holds_alternative<SphereDesc>(s.projectedThrough[0]->shape));
  CHECK(s.objects.empty());
}

TEST_CASE("povray scene: a finish's emission is added to its ambient, which alone ambient_light scales; an "
          "interior's fade and caustics", "[povray]") {
  const SceneDesc s = scene(R"(
global_settings { ambient_light 0.5 }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.25> } finish { ambient 0.2 emission 0.5 }
         interior { fade_distance 2 fade_power 3 fade_color <1, 0, 0> } }
sphere { 0, 1 interior { fade_distance 2 } }
)");
  REQUIRE(s.objects.size() == 2);
  REQUIRE(s.objects[0].texture);
  const Material m = s.objects[0].texture->at(glm::dvec3(0));
  CHECK(m.ambient.r == Approx(0.6f));  // (0.2·0.5 + 0.5)·C
  CHECK(m.ambient.g == Approx(0.3f));
  CHECK(m.ambient.b == Approx(0.15f));
  CHECK(m.extras->fadeDistance == 2);
  CHECK(m.extras->fadePower == 3);
  CHECK(m.extras->fadeColor == Color(1, 0, 0));
  CHECK(s.objects[1].material.extras->fadeDistance == 0);  // fade_power 0, its default: no fade
  CHECK(scene("sphere { 0, 1 interior { caustics 0.5 } }\n").objects[0].material.extras->caustics == 0.5f);
  CHECK(scene("sphere { 0, 1 finish { crand 0.05 } }\n").objects[0].material.extras->crand == 0.05f);
}

TEST_CASE("povray scene: a reflection block: one value, two that vary with the angle, falloff, fresnel, metallic",
          "[povray]") {
  const SceneDesc s = scene(R"(
sphere { 0, 1 finish { reflection { 0.3 } } }
sphere { 0, 1 finish { reflection { 0.2, 0.8 falloff 3 } } }
sphere { 0, 1 finish { reflection { 1 fresnel } } interior { ior 1.5 } }
sphere { 0, 1 finish { reflection { 0.1, 1 fresnel on exponent 1 } } }
sphere { 0, 1 finish { reflection { 0.5 metallic } } }
sphere { 0, 1 finish { reflection { 0.5 metallic 0.25 } } }
)");
  REQUIRE(s.objects.size() == 6);
  CHECK(s.objects[0].material.reflection == 0.3f);
  CHECK(s.objects[0].material.extras->reflectionFalloff == 0);  // constant
  CHECK(s.objects[1].material.extras->reflectionMin == 0.2f);
  CHECK(s.objects[1].material.reflection == 0.8f);
  CHECK(s.objects[1].material.extras->reflectionFalloff == 3);
  CHECK(s.objects[2].material.extras->reflectionFresnel);
  CHECK(s.objects[2].material.extras->reflectionMin == 0);  // one value with fresnel: from 0 (POV-Ray's picture)
  CHECK(s.objects[2].material.ior == 1.5f);
  CHECK(s.objects[3].material.extras->reflectionMin == 0.1f);
  CHECK(failure("sphere { 0, 1 finish { reflection { 0.5 exponent 2 } } }\n") ==
        "scene.pov:3:41: error: 'exponent' is not supported yet");
  CHECK(s.objects[0].material.extras->reflectionMetallic == 0);
  CHECK(s.objects[4].material.extras->reflectionMetallic == 1);  // the value is optional
  CHECK(s.objects[5].material.extras->reflectionMetallic == 0.25f);
  // A colour: its largest channel is the reflection, the colour over it the tint; a grey one has none.
  const SceneDesc c = scene(R"(
sphere { 0, 1 finish { reflection rgb <0.5, 0.25, 0.1> } }
sphere { 0, 1 finish { reflection { rgb <0.1, 0.2, 0.05>, rgb <0.2, 0.4, 0.1> } } }
sphere { 0, 1 finish { reflection rgb 0.5 } }
)");
  REQUIRE(c.objects.size() == 3);
  CHECK(c.objects[0].material.reflection == 0.5f);
  CHECK(c.objects[0].material.extras->reflectionTint == Color(1, 0.5f, 0.2f));
  CHECK(c.objects[1].material.reflection == 0.4f);
  CHECK(c.objects[1].material.extras->reflectionMin == 0.2f);
  CHECK(c.objects[1].material.extras->reflectionTint == Color(0.5f, 1, 0.25f));
  CHECK(c.objects[2].material.extras == &kNoExtras);
  CHECK(c.objects[1].material.extras->reflectionMinTint == Color(0.5f, 1, 0.25f));
  const SceneDesc hues = scene("sphere { 0, 1 finish { reflection { rgb <0.5, 0, 0>, rgb <0, 0.25, 0> } } }\n");
  CHECK(hues.objects[0].material.extras->reflectionMin == 0.5f);
  CHECK(hues.objects[0].material.extras->reflectionMinTint == Color(1, 0, 0));
  CHECK(hues.objects[0].material.reflection == 0.25f);
  CHECK(hues.objects[0].material.extras->reflectionTint == Color(0, 1, 0));
}

TEST_CASE("povray scene: textures take the transforms after them, at every level, and pass to CSG children",
          "[povray]") {
  const SceneDesc s = scene(R"(
#declare Ball = sphere { 0, 1 translate 5*x pigment { gradient x color_map { [0 Black] [1 White] } } translate y }
object { Ball translate z }
intersection { sphere { 0, 1 } box { -1, 0.5 } pigment { checker Red Blue } scale 2 }
)");
  REQUIRE(s.objects.size() == 2);
  // The gradient moved by the translations after it (y, then z): x is unmoved, so world x = 0.25 reads 0.25.
  REQUIRE(s.objects[0].texture);
  CHECK(s.objects[0].texture->at(glm::dvec3(0.25, 1, 1)).pigment.r == Approx(0.25f));
  const auto& csg = std::get<CsgDesc>(s.objects[1].shape);
  REQUIRE(csg.children[1].texture);
  // The checker scaled by 2 with the group: world (1.5, 0.5, 0.5) lies in the first cube.
  CHECK(csg.children[1].texture->at(glm::dvec3(1.5, 0.5, 0.5)).pigment == Color(1, 0, 0));
  CHECK(csg.children[1].texture->at(glm::dvec3(2.5, 0.5, 0.5)).pigment == Color(0, 0, 1));
}

TEST_CASE("povray scene: an orthographic camera's size: its right and up, or what a perspective camera shows at "
          "look_at", "[povray]") {
  const SceneDesc own = scene("camera { orthographic location <0, 0, -10> look_at 0 right 8*x up 6*y }\n");
  CHECK(own.camera.projection == rt::projectionNamed("orthographic"));
  CHECK(own.camera.right == glm::dvec3(8, 0, 0));
  CHECK(own.camera.up == glm::dvec3(0, 6, 0));
  // With angle 90 a perspective camera shows 2·10·tan 45° = 20 units across at the look_at point.
  const SceneDesc angled = scene("camera { orthographic location <0, 0, -10> look_at 0 right 4/3*x angle 90 }\n");
  CHECK(angled.camera.right.x == Approx(20));
  CHECK(angled.camera.up.y == Approx(15));
}

TEST_CASE("povray scene: a pattern of whole textures picks or blends them, each with its finish", "[povray]") {
  const SceneDesc s = scene(R"(
#default { finish { ambient 0.2 } }
plane { y, 0 texture { checker texture { pigment { Red } finish { diffuse 0.5 } } texture { pigment { Blue } } scale 2 } }
plane { y, 0 texture { gradient x texture_map { [0 texture { pigment { Black } }] [1 texture { pigment { White } finish { phong 1 } }] } } }
)");
  REQUIRE(s.objects.size() == 2);
  const Texture& checker = *s.objects[0].texture;
  const Material red = checker.at(glm::dvec3(1, 0, 1)), blue = checker.at(glm::dvec3(3, 0, 1));
  CHECK(red.diffuse == Color(0.5f, 0, 0));
  CHECK(red.ambient == Color(0.2f, 0, 0));  // the texture starts as #default's
  CHECK(blue.diffuse == Color(0, 0, 0.6f));
  CHECK(checker.bound.diffuse == Color(0.5f, 0, 0.6f));
  const Material mid = s.objects[1].texture->at(glm::dvec3(0.25, 0, 0));
  CHECK(mid.pigment.r == Approx(0.25f));
}

TEST_CASE("povray scene: a lone pigment colour takes the #default surface in force where the object is", "[povray]") {
  const SceneDesc s = scene(R"(
sphere { 0, 1 pigment { rgb <1, 0.5, 0> } }
#default { finish { ambient 0.2 diffuse 0.8 } }
sphere { 0, 1 pigment { rgb <1, 0.5, 0> } }
sphere { 0, 1 pigment { rgbf <1, 0.5, 0, 0.5> } finish { phong 1 } }
#default { pigment { checker } }
sphere { 0, 1 pigment { rgb <1, 0.5, 0> } }
sphere { 0, 1 }
)");
  REQUIRE(s.objects.size() == 5);
  // POV-Ray's default finish: ambient 0.1, diffuse 0.6.
  CHECK(s.objects[0].material.ambient == Color(0.1f, 0.05f, 0));
  CHECK(s.objects[0].material.diffuse == Color(0.6f, 0.3f, 0));
  CHECK(s.objects[1].material.ambient == Color(0.2f, 0.1f, 0));
  CHECK(s.objects[1].material.diffuse == Color(0.8f, 0.4f, 0));
  // A finish after the colour: both, over the #default.
  CHECK(s.objects[2].material.filter == 0.5f);
  CHECK(s.objects[2].material.diffuse == Color(0.8f, 0.4f, 0));
  CHECK(s.objects[2].material.specular == Color(1));
  // Over a #default checker the colour replaces the pattern; without a pigment the object has the checker.
  CHECK(!s.objects[3].texture);
  CHECK(s.objects[3].material.diffuse == Color(0.8f, 0.4f, 0));
  CHECK(s.objects[4].texture);
}

// n·l of a normal's bent normal on the plane y = 0 at a point, as POV-Ray lit it: a white matte plane under a
// distant light, each value read once from POV-Ray's 16-bit render.
double lit(const SceneDesc& s, size_t object, const glm::dvec3& point, const glm::dvec3& toLight) {
  return glm::dot(s.objects[object].texture->bent(point, glm::dvec3(0, 1, 0)), glm::normalize(toLight));
}

TEST_CASE("povray scene: a normal bends the shading normal as POV-Ray's renders show", "[povray]") {
  const SceneDesc s = scene(R"(
#declare N = normal { gradient x 1 }
plane { y, 0 pigment { White } normal { gradient x 0.5 } }
plane { y, 0 pigment { White } normal { N scale <1, 0.5, 1> } }
plane { y, 0 pigment { White } normal { N bump_size 2 } }
plane { y, 0 pigment { White } normal { gradient x 1 scale 0.5 no_bump_scale } }
plane { y, 0 texture { pigment { White } normal { gradient x 1 slope_map { [0 <0, 1>] [0.5 <0.5, 1>] [1 <1, 1>] } } } }
plane { y, 0 texture { pigment { White } normal { N } scale 0.5 } }
plane { y, 0 texture { checker texture { pigment { White } normal { gradient x 0.5 } } texture { pigment { White } } } }
plane { y, 0 pigment { White } normal { quilted 1 control0 0 control1 0.5 } }
plane { y, 0 pigment { White } normal { quilted 0.7 scale 0.5 } }
plane { y, 0 pigment { White } normal { bumps 1 } }
plane { y, 0 pigment { White } normal { bumps 0.6 scale 0.3 } }
plane { y, 0 pigment { White } normal { dents 1 } }
plane { y, 0 pigment { White } normal { bumps 1 turbulence 0.5 } }
plane { y, 0 pigment { White } normal { ripples 0.5 frequency 3 phase 0.2 } }
plane { y, 0 pigment { White } normal { gradient x normal_map { [0 gradient z 2] [1 gradient -z 2] } } }
plane { y, 0 pigment { White } normal { average normal_map { [3 gradient x 6] [gradient z 6] } } }
)");
  REQUIRE(s.objects.size() == 16);
  const glm::dvec3 up(0, 1, 0), left(-1, 1, 0), right(1, 1, 0), p(0.5, 0, 0.45);
  CHECK(lit(s, 0, p, up) == Approx(0.9978).margin(1e-4));
  CHECK(lit(s, 0, p, left) == Approx(0.7526).margin(1e-4));
  CHECK(lit(s, 0, p, right) == Approx(0.6585).margin(1e-4));
  CHECK(lit(s, 1, p, left) == Approx(0.7526).margin(1e-4));
  CHECK(lit(s, 2, p, left) == Approx(0.8654).margin(1e-4));
  CHECK(lit(s, 3, {0.25, 0, 0.45}, up) == Approx(0.9662).margin(1e-4));
  CHECK(lit(s, 4, {0.95, 0, 0.45}, left) == Approx(0.8321).margin(1e-4));
  CHECK(lit(s, 4, {0.75, 0, 0.45}, left) == Approx(0.7528).margin(1e-4));
  CHECK(lit(s, 5, {0.35, 0, 0.45}, left) == Approx(0.7944).margin(1e-4));
  // Across the wrap of the gradient at x = 0, where the pyramid's corners straddle it.
  CHECK(lit(s, 5, {0.0025, 0, 0.45}, up) == Approx(0.6872).margin(1e-4));
  CHECK(lit(s, 5, {0.0025, 0, 0.45}, right) == Approx(0.9996).margin(1e-4));
  CHECK(lit(s, 5, {-0.0075, 0, 0.45}, right) == Approx(0.5979).margin(1e-4));
  CHECK(lit(s, 6, {0.5, 0, 0.5}, left) == Approx(0.7526).margin(1e-4));
  CHECK(lit(s, 6, {1.5, 0, 0.5}, left) == Approx(0.7071).margin(1e-4));
  CHECK(lit(s, 7, {0.95, 0, 0.45}, right) == Approx(0.9169).margin(1e-4));
  CHECK(lit(s, 8, {0.95, 0, 0.45}, right) == Approx(0.8657).margin(1e-4));
  CHECK(lit(s, 9, {0.45, 0, 0.45}, up) == Approx(0.8757).margin(1e-4));
  CHECK(lit(s, 9, {0.45, 0, 0.45}, right) == Approx(0.3279).margin(1e-4));
  CHECK(lit(s, 10, {0.95, 0, 0.45}, up) == Approx(0.9934).margin(1e-4));
  CHECK(lit(s, 10, {0.95, 0, 0.45}, right) == Approx(0.6567).margin(1e-4));
  CHECK(lit(s, 11, {0.05, 0, 0.45}, up) == Approx(0.9992).margin(1e-4));
  CHECK(lit(s, 11, {0.05, 0, 0.45}, glm::dvec3(0, 1, 1)) == Approx(0.6777).margin(1e-4));
  CHECK(failure("plane { y, 0 normal { facets 0.4 } }\n") == "scene.pov:3:23: error: 'facets' is not supported yet");
  CHECK(lit(s, 12, {0.95, 0, 0.45}, up) == Approx(0.7177).margin(1e-4));
  CHECK(lit(s, 12, {0.95, 0, 0.45}, right) == Approx(0.0908).margin(1e-4));
  // frequency and phase reach ripples' own formula (surface/test_normal.cpp).
  CHECK(lit(s, 13, {-1.3125, 0, 1.0625}, up) == Approx(0.9986).margin(1e-4));
  CHECK(lit(s, 13, {-1.3125, 0, 1.0625}, right) == Approx(0.6929).margin(1e-4));
  // A normal_map and an average (surface/test_normal.cpp), from POV-Ray's renders; an average's weight is 1
  // when left out.
  CHECK(lit(s, 14, {0.125, 0, 0.5}, up) == Approx(0.98058).margin(1e-4));
  CHECK(lit(s, 15, {0.5, 0, 0.5}, glm::dvec3(0, 1, 1)) == Approx((0.8451514 - 0.1690221) / std::sqrt(2)).margin(1e-4));
  CHECK(failure("plane { y, 0 normal { gradient x normal_map { gradient y } } }\n") ==
        "scene.pov:3:47: error: a normal_map entry is [value normal]");
  CHECK(failure("plane { y, 0 normal { average } }\n") == "scene.pov:3:14: error: 'average' needs a normal_map");
  CHECK(failure("plane { y, 0 normal { gradient x bump_map { png \"a.png\" } } }\n") ==
        "scene.pov:3:49: error: cannot find the image map \"a.png\"");
  CHECK(failure("plane { y, 0 normal { gradient x slope_map { [0] } } }\n") ==
        "scene.pov:3:46: error: a slope_map entry is [value, <height, slope>]");
}

TEST_CASE("povray scene: a transform after a layered texture moves every layer", "[povray]") {
  const SceneDesc s = scene(R"(
#declare Layers = texture { pigment { gradient x color_map { [0 Black] [1 White] } } }
                  texture { pigment { gradient x color_map { [0 rgbt <1, 0, 0, 1>] [1 rgbt <1, 0, 0, 1>] } } }
plane { y, 0 texture { Layers scale 4 } }
)");
  REQUIRE(s.objects.size() == 1);
  // The bottom gradient scaled by 4 too: at x = 1 it reads 0.25 under the clear top layer.
  const Material m = s.objects[0].texture->at(glm::dvec3(1, 0, 0));
  CHECK(m.pigment.g == Approx(0.25f));
}

TEST_CASE("povray scene: each layer of a layered texture starts as the #default texture", "[povray]") {
  const SceneDesc s = scene(R"(
#default { finish { ambient 0.3 diffuse 0.9 } }
plane { y, 0 texture { pigment { White } finish { diffuse 0.2 } } texture { pigment { rgb 0.5 } } }
plane { y, 0 texture { pigment { White } finish { diffuse 0.2 } } translate x texture { pigment { rgb 0.5 } } }
)");
  REQUIRE(s.objects.size() == 2);
  for (const ObjectDesc& o : s.objects) {
    // The opaque top layer, with #default's diffuse 0.9 on its grey.
    CHECK(o.texture->at(glm::dvec3(0)).diffuse == Color(0.45f));
  }
}

TEST_CASE("povray scene: turbulence and its modifiers may follow the map; a pattern's own noise_generator", "[povray]") {
  const SceneDesc s = scene(R"(
#declare Grain = pigment { wood color_map { [0 Black] [1 White] } }
plane { y, 0 pigment { Grain turbulence 0.5 octaves 3 } }
plane { y, 0 pigment { Grain } }
global_settings { noise_generator 1 }
)");
  REQUIRE(s.objects.size() == 2);
  // Away from the z axis the turbulence bends the rings: the two planes differ there.
  const glm::dvec3 p(0.3, 0, 0.2);
  CHECK(s.objects[0].texture->at(p).pigment.r != Approx(s.objects[1].texture->at(p).pigment.r));
  // No map: a grey ramp.
  const SceneDesc ramp = scene("plane { y, 0 pigment { gradient x } }\n");
  CHECK(ramp.objects[0].texture->at(glm::dvec3(0.25, 0, 0)).pigment == Color(0.25f));
  // A second rgb starts the next colour, as POV-Ray reads it.
  const SceneDesc two = scene("plane { y, 0 pigment { checker rgb <1, 0, 0> rgb <0, 0, 1> } }\n");
  CHECK(two.objects[0].texture->at(glm::dvec3(0.5, 0, 0.5)).pigment == Color(1, 0, 0));
  CHECK(two.objects[0].texture->at(glm::dvec3(1.5, 0, 0.5)).pigment == Color(0, 0, 1));
  // A colour identifier's filter changed after it.
  const SceneDesc filtered = scene("plane { y, 0 pigment { Red filter 0.9 } }\n");
  CHECK(filtered.objects[0].material.filter == Approx(0.9f));
  // An average's entries without weights weigh 1 each.
  const SceneDesc mixed = scene("plane { y, 0 pigment { average pigment_map { [pigment { Red }] [3 Blue] } } }\n");
  CHECK(mixed.objects[0].texture->at(glm::dvec3(0)).pigment == Color(0.25f, 0, 0.75f));
  // Generator 3 where the scene's is 1: POV-Ray's bozo there is 0.6925634427549031.
  const SceneDesc perlin = scene("plane { y, 0 pigment { bozo noise_generator 3 color_map { [0 rgb 0] [1 rgb 1] } } }\n"
                                 "global_settings { noise_generator 1 }\n");
  CHECK(perlin.objects[0].texture->at(glm::dvec3(0.3, 0.4, 0.7)).pigment.r == Approx(0.6925634427549031).margin(1e-6));
  CHECK(failure("plane { y, 0 pigment { spiral1 2 turbulence 0.3 } }\n") ==
        "scene.pov:3:14: error: 'turbulence on spiral1' is not supported yet");
  CHECK(failure("plane { y, 0 pigment { bozo octaves <1, 2, 3> color_map { [0 Red] [1 Blue] } } }\n") ==
        "scene.pov:3:29: error: 'octaves' needs a float");
}

TEST_CASE("povray scene: a turbulence warp displaces the point where it stands among the transforms", "[povray]") {
  // Values POV-Ray printed for function { pattern { … } } at the same points.
  const SceneDesc s = scene(R"(
plane { y, 0 pigment { bozo scale 2 warp { turbulence 0.5 } color_map { [0 Black] [1 White] } } }
plane { y, 0 pigment { bozo warp { turbulence 0.5 } scale 2 color_map { [0 Black] [1 White] } } }
)");
  REQUIRE(s.objects.size() == 2);
  const glm::dvec3 a(0.3, 0.7, 0.2), b(1.7, -0.4, 0.9);
  CHECK(s.objects[0].texture->at(a).pigment.r == Approx(0.2868780100536544).margin(1e-6));
  CHECK(s.objects[0].texture->at(b).pigment.r == Approx(0.3254249134030404).margin(1e-6));
  CHECK(s.objects[1].texture->at(a).pigment.r == Approx(0.1557192993952387).margin(1e-6));
  CHECK(s.objects[1].texture->at(b).pigment.r == Approx(0.3909708381241105).margin(1e-6));
}

TEST_CASE("povray scene: a normal's warps move the point its bumps are sampled round", "[povray][warp]") {
  // POV-Ray samples the pattern round the warped point and bends the normal by the transforms alone: through a
  // spherical warp, gradient x bends every point alike.
  const SceneDesc s = scene(R"(
plane { y, 0 pigment { White } normal { gradient x 1 warp { spherical } } }
plane { y, 0 pigment { White } normal { bumps 1 scale 0.3 warp { turbulence 0.5 } scale 2 } }
plane { y, 0 texture { pigment { White } normal { quilted 0.6 scale 0.25 warp { turbulence 0.1 octaves 2 } } } }
)");
  REQUIRE(s.objects.size() == 3);
  const glm::dvec3 up(0, 1, 0), right(1, 1, 0), back(0, 1, 1), p(0.5, 0, 0.45), q(-0.3, 0, 0.6);
  CHECK(lit(s, 0, p, up) == Approx(0.9912).margin(1e-4));
  CHECK(lit(s, 0, p, right) == Approx(0.6074).margin(1e-4));
  CHECK(lit(s, 0, q, right) == Approx(0.6074).margin(1e-4));
  CHECK(lit(s, 0, q, back) == Approx(0.7009).margin(1e-4));
  CHECK(lit(s, 1, p, up) == Approx(0.9927).margin(1e-4));
  CHECK(lit(s, 1, p, right) == Approx(0.6918).margin(1e-4));
  CHECK(lit(s, 1, p, back) == Approx(0.6171).margin(1e-4));
  CHECK(lit(s, 2, p, up) == Approx(0.9532).margin(1e-4));
  CHECK(lit(s, 2, p, right) == Approx(0.7983).margin(1e-4));
  CHECK(lit(s, 2, p, back) == Approx(0.8480).margin(1e-4));
}

TEST_CASE("povray scene: agate, bozo, marble, radial and wood without a map take their own colour maps", "[povray]") {
  // The colours POV-Ray's pigment functions gave at the same points; spotted keeps the grey ramp.
  const SceneDesc s = scene("plane { y, 0 pigment { radial } }\nplane { y, 0 pigment { bozo } }\n"
                            "plane { y, 0 pigment { marble } }\nplane { y, 0 pigment { wood } }\n"
                            "plane { y, 0 pigment { agate } }\nplane { y, 0 pigment { spotted } }\n");
  REQUIRE(s.objects.size() == 6);
  const glm::dvec3 a(-2.193815, 2.084602, 1.582648), b(-1.469586, -0.027389, -0.303054);
  const auto near = [&](size_t i, const glm::dvec3& p, Color expected) {
    const Color c = s.objects[i].texture->at(p).pigment;
    INFO("object " << i);
    CHECK(c.r == Approx(expected.r).margin(2e-6));
    CHECK(c.g == Approx(expected.g).margin(2e-6));
    CHECK(c.b == Approx(expected.b).margin(2e-6));
  };
  near(0, a, Color(1.0f, 0.199807f, 0.800193f));
  near(0, b, Color(1.0f, 0.595696f, 0.404304f));
  near(1, a, Color(1, 1, 1));
  near(1, b, Color(0, 0, 1));
  near(2, a, Color(0.9f, 0.489928f, 0.489928f));
  near(2, b, Color(0, 0, 0));
  near(3, a, Color(0.666f, 0.312f, 0.2f));
  near(3, b, Color(0.4f, 0.1333f, 0.066f));
  near(4, a, Color(0.904289f, 0.604289f, 0.304289f));
  near(4, b, Color(0.9f, 0.7f, 0.413192f));
  const Color grey = s.objects[5].texture->at(a).pigment;
  CHECK((grey.r == grey.g && grey.g == grey.b));
}

TEST_CASE("povray scene: the warps, their items and their refusals", "[povray][warp]") {
  // gradient x over [-50, 50) reads the warped point's x; values POV-Ray printed for the same pigments.
  const SceneDesc s = scene(R"(
#macro G(W) pigment { gradient x color_map { [0 Black] [1 White] } scale 100 translate -50*x W } #end
plane { y, 0 G(warp { repeat 2*x offset <0.1,0.2,0.05> flip <1,1,0> }) }
plane { y, 0 G(warp { black_hole <0.5,0.5,0>, 0.5 falloff 1 strength 0.7 inverse }) }
plane { y, 0 G(warp { black_hole <0.5,0.5,0.5>, 0.4 repeat <1,1,1> }) }
plane { y, 0 G(warp { planar <1,1,0>, 0.5 }) }
plane { y, 0 G(warp { spherical orientation y dist_exp 1 }) }
plane { y, 0 G(warp { toroidal major_radius 2 }) }
plane { y, 0 G(warp { cubic }) }
plane { y, 0 G(warp { cylindrical orientation 2*x dist_exp 2 }) }
)");
  REQUIRE(s.objects.size() == 8);
  const auto x = [&](size_t i, glm::dvec3 p) { return 100 * double(s.objects[i].texture->at(p).pigment.r) - 50; };
  CHECK(x(0, {2.3, 0.2, 0.1}) == Approx(1.800001).margin(2e-5));
  CHECK(x(0, {-0.7, 0.4, 0.6}) == Approx(0.599998).margin(2e-5));
  CHECK(x(1, {0.3, 0.2, 0.1}) == Approx(0.335234).margin(2e-5));
  CHECK(x(2, {-2.6, 1.5, -0.4}) == Approx(-2.641788).margin(2e-5));
  CHECK(x(3, {4.9, -0.3, 0.2}) == Approx(3.818375).margin(2e-5));
  CHECK(x(4, {0.3, 0.2, 0.1}) == Approx(0.019160).margin(2e-5));
  CHECK(x(5, {0.5, -0.7, -0.3}) == Approx(0.913990).margin(2e-5));
  CHECK(x(6, {0.7, 0.1, -1.2}) == Approx(0.802080).margin(2e-5));
  CHECK(x(7, {-2.6, 1.5, -0.4}) == Approx(2.630590).margin(2e-5));
  CHECK(failure("plane { y, 0 pigment { bozo warp { repeat <1,1,0> } } }\n") ==
        "scene.pov:3:36: error: a repeat warp's vector must lie along one axis");
  CHECK(failure("plane { y, 0 pigment { bozo warp { black_hole 0, 0 } } }\n") ==
        "scene.pov:3:36: error: a black hole's radius must be greater than 0");
  CHECK(failure("plane { y, 0 pigment { bozo warp { black_hole 0.2, 0.4 repeat 1 turbulence 0.2 } } }\n") ==
        "no error");
  CHECK(failure("plane { y, 0 pigment { bozo warp { planar 0, 1 } } }\n") ==
        "scene.pov:3:36: error: a planar warp's normal is zero");
  CHECK(failure("plane { y, 0 pigment { bozo warp { spherical orientation 0 } } }\n") ==
        "scene.pov:3:46: error: a warp's orientation is zero");
  CHECK(failure("plane { y, 0 pigment { bozo warp { cylindrical major_radius 2 } } }\n") ==
        "scene.pov:3:48: error: only a toroidal warp takes 'major_radius'");
  CHECK(failure("plane { y, 0 pigment { bozo warp { repeat x strength 1 } } }\n") ==
        "scene.pov:3:45: error: 'strength' is not supported yet");
}

TEST_CASE("povray scene: min_extent, max_extent and trace ask the object; a macro's arguments may omit commas",
          "[povray]") {
  // What POV-Ray printed for the same lines.
  std::ostringstream printed;
  std::streambuf* const old = std::cerr.rdbuf(printed.rdbuf());
  parsePovRay(R"(#version 3.7;
#declare S = sphere { <1, 2, 3>, 1 }
#declare U = union { object { S } box { -1, <0.5, 0.5, 0.5> translate -x } }
#debug concat(vstr(3, min_extent(S), ",", 0, 3), " ", vstr(3, max_extent(S), ",", 0, 3), "\n")
#debug concat(vstr(3, min_extent(U), ",", 0, 3), " ", vstr(3, max_extent(U), ",", 0, 3), "\n")
#macro Add(A, B) (A + B) #end
#debug concat(str(Add(1 2), 0, 1), "\n")
#declare E = sphere { <0, 0, 0>, 2 scale <1, 0.5, 1> translate x }
#declare N = <9, 9, 9>;
#declare P = trace(E, <1, 5, 0>, -y, N);
#debug concat(vstr(3, P, ",", 0, 4), " ", vstr(3, N, ",", 0, 4), "\n")
#declare Q = trace(E, <10, 5, 0>, -y, N);
#debug concat(vstr(3, Q, ",", 0, 4), " ", vstr(3, N, ",", 0, 4), "\n")
#declare R = trace(U, <-1.5, 0, -5>, z);
#debug concat(vstr(3, R, ",", 0, 4), "\n")
)", "scene.pov", PovRayOptions{{}, 320, 240, true});
  std::cerr.rdbuf(old);
  CHECK(printed.str() ==
        "0.000,1.000,2.000 2.000,3.000,4.000\n-2.000,-1.000,-1.000 2.000,3.000,4.000\n3.0\n"
        "1.0000,1.0000,0.0000 0.0000,1.0000,0.0000\n0.0000,0.0000,0.0000 0.0000,0.0000,0.0000\n"
        "-1.5000,0.0000,-1.0000\n");
  CHECK(failure("#declare L = ovus { 1, 0.5 }\n#declare V = trace(L, 5*x, -x);\n") ==
        "scene.pov:3:14: error: 'ovus' is not supported yet");
  CHECK(failure("#declare P = plane { y, 0 }\n#declare V = min_extent(P);\n") ==
        "scene.pov:4:25: error: 'min_extent' of an object without bounds, such as a plane");
}

TEST_CASE("povray scene: inside asks the object; vturbulence is a pattern's turbulence displacement", "[povray]") {
  // What POV-Ray printed for the same lines.
  std::ostringstream printed;
  std::streambuf* const old = std::cerr.rdbuf(printed.rdbuf());
  parsePovRay(R"(#version 3.7;
#declare S = sphere { <1, 2, 3>, 1 }
#declare U = union { object { S } box { -1, <0.5, 0.5, 0.5> translate -x } }
#declare D = difference { box { -1, 1 } sphere { 0, 0.8 } }
#debug concat(str(inside(S, <1, 2, 3.5>), 0, 0), str(inside(S, <1, 2, 4.5>), 0, 0), str(inside(U, <-1.5, 0, 0>), 0, 0), str(inside(U, 0), 0, 0), str(inside(D, 0), 0, 0), str(inside(D, 0.9*x), 0, 0), "\n")
#debug concat(vstr(3, vturbulence(2, 0.5, 6, <0.3, 0.2, 0.1>), ",", 0, 9), "\n")
#debug concat(vstr(3, vturbulence(3, 0.7, 3, <-5.5, 3.3, 1.1>), ",", 0, 9), "\n")
)", "scene.pov", PovRayOptions{{}, 320, 240, true});
  std::cerr.rdbuf(old);
  CHECK(printed.str() == "101001\n-0.426615880,-0.193939078,-0.365478993\n0.172241169,0.007014960,0.000509631\n");
  CHECK(failure("#declare V = inside(1, 0);\n") == "scene.pov:3:21: error: expected an object, found a float");
}


TEST_CASE("povray scene: a camera whose up lies along its direction has right flipped, as POV-Ray's pictures show",
          "[povray]") {
  // objects/prism3.inc's camera: up z and the default direction z make up × direction zero.
  const SceneDesc s = scene("camera { location <-10, 10, -10> right x*4/3 up z look_at 0 angle 20 }\n");
  const glm::dvec3 toward = glm::normalize(s.camera.lookAt - s.camera.location);
  // Seen along the view, right points to the left of the usual left-handed frame: (up × direction) · right > 0.
  CHECK(glm::dot(glm::cross(s.camera.up, toward), s.camera.right) < 0);
}

TEST_CASE("povray scene: a shape or group that cannot be drawn yet is refused where it is written", "[povray]") {
  CHECK(failure("union { sphere { 0, 1 }\n ovus { 1, 0.5 } }\n") == "scene.pov:4:2: error: 'ovus' is not supported yet");
  CHECK(failure("intersection { sphere { 0, 1 } plane { y, 0 } cutaway_textures }\n") ==
        "scene.pov:3:47: error: 'cutaway_textures' is not supported yet");
  CHECK(failure("sphere { 0 }\n") == "scene.pov:3:1: error: 'sphere' needs the sphere radius");
  CHECK(failure("sphere { 0, -1 }\n") == "scene.pov:3:13: error: the sphere radius must be greater than 0, found -1");
  CHECK(failure("difference { pigment { Red } }\n") == "scene.pov:3:14: error: expected an object inside 'difference'");
}

TEST_CASE("povray scene: torus, quadric, cubic, quartic and poly, their coefficient lists and sturm", "[povray]") {
  const SceneDesc s = scene(R"(
#declare C = 2;
torus { 2, 0.5 pigment { Red } sturm }
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
cubic { <1,0,0,0, 0,0,0, 0,0,0, 1,0,0, 0,0,0, 1,0,0, -1> translate <C, 0, 0> }
#declare Q = quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 56, 0,
                        0, 0, 0, 1, 0, -104, 0, 392 * C> }
object { Q sturm }
torus { 1, 0.25 sturm off }
poly { 3 - 1, <1 0 0 0 1 0 0 1 0, -1> }  // without commas, as POV-Ray allows
)");
  REQUIRE(s.objects.size() == 6);
  CHECK(std::get<TorusDesc>(s.objects[0].shape).sturm);
  CHECK(s.objects[0].material.pigment == Color(1, 0, 0));
  CHECK(std::get<QuadricDesc>(s.objects[1].shape).squares == glm::dvec3(1));
  const auto& cubic = std::get<PolyDesc>(s.objects[2].shape);
  CHECK(cubic.order == 3);
  CHECK(cubic.coefficients.size() == 20);
  CHECK(cubic.coefficients[19] == -1);
  CHECK_FALSE(cubic.sturm);
  CHECK(s.objects[2].transforms.size() == 1);
  const auto& quartic = std::get<PolyDesc>(s.objects[3].shape);
  CHECK(quartic.coefficients.size() == 35);
  CHECK(quartic.coefficients[34] == 784);
  CHECK(quartic.sturm);
  CHECK_FALSE(std::get<TorusDesc>(s.objects[4].shape).sturm);
  const auto& poly = std::get<PolyDesc>(s.objects[5].shape);
  CHECK(poly.order == 2);
  CHECK(poly.coefficients == std::vector<double>{1, 0, 0, 0, 1, 0, 0, 1, 0, -1});
}

TEST_CASE("povray scene: impossible polynomial shapes, each refused where it is written", "[povray]") {
  CHECK(failure("torus { 1, 0 }\n") == "scene.pov:3:12: error: the torus minor radius must be greater than 0, found 0");
  CHECK(failure("poly { 1, <1, 2, 3, 4> }\n") == "scene.pov:3:8: error: the poly order must be from 2 to 7, found 1");
  CHECK(failure("poly { 8, <1, 2, 3, 4> }\n") == "scene.pov:3:8: error: the poly order must be from 2 to 7, found 8");
  CHECK(failure("cubic { <1, 2, 3, 4, 5, 6> }\n") == "scene.pov:3:9: error: the cubic coefficients need 20 numbers, found 6");
  CHECK(failure("quartic { <1, 2> }\n") == "scene.pov:3:11: error: the quartic coefficients need 35 numbers, found 2");
  CHECK(failure("poly { 2, <0, 0, 0, 0, 0, 0, 0, 0, 0, 1> }\n") ==
        "scene.pov:3:11: error: the poly coefficients of x, y and z are all zero");
  CHECK(failure("quadric { 0, 0, 0, 1 }\n") == "scene.pov:3:11: error: the quadric's coefficients of x, y and z are all zero");
  CHECK(failure("cubic { <1, 2, x> }\n") == "scene.pov:3:16: error: a coefficient must be a float, found a vector");
}

TEST_CASE("povray scene: open on cylinders and cones, no_image and no_reflection on any object and a union's parts",
          "[povray]") {
  const SceneDesc s = scene(
      "cylinder { 0, y, 1 open }\ncone { 0, 1, y, 0.5 pigment { Red } open }\n"
      "union { sphere { 0, 1 } sphere { x, 1 no_shadow } no_image }\nbox { 0, 1 no_reflection }\n");
  REQUIRE(s.objects.size() == 5);
  CHECK(std::get<CylinderDesc>(s.objects[0].shape).open);
  CHECK(std::get<ConeDesc>(s.objects[1].shape).open);
  CHECK(s.objects[2].noImage);
  CHECK(s.objects[3].noImage);
  CHECK(s.objects[3].noShadow);
  CHECK_FALSE(s.objects[3].noReflection);
  CHECK(s.objects[4].noReflection);
  CHECK_FALSE(s.objects[4].noImage);
  CHECK(failure("sphere { 0, 1 open }\n") == "scene.pov:3:15: error: 'open' is not supported yet");
}

}  // namespace
}  // namespace rt::povray
