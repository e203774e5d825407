// A parsed scene: what the file says, in double precision, before any precision choice or acceleration.
// Both scene languages (POV subset and .cli) produce this; Scene<T> (scene.hpp) is built from it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "raytrace/util/error.hpp"
#include "raytrace/scene/dialect.hpp"
#include "raytrace/scene/light_kind.hpp"
#include "raytrace/scene/radiosity.hpp"
#include "raytrace/scene/projection.hpp"
#include "raytrace/shapes/shape_desc.hpp"
#include "raytrace/surface/environment.hpp"
#include "raytrace/surface/material.hpp"
#include "raytrace/surface/normal.hpp"

namespace rt {

struct CameraDesc {
  glm::dvec3 location{0, 0, 0};
  glm::dvec3 up{0, 1, 0};
  glm::dvec3 right{1.33333, 0, 0};  // carries the aspect ratio; not normalized (§d)
  glm::dvec3 lookAt{0, 0, -1};
  // Where in a pixel the eye ray passes, in pixel units from the pixel's lower-left corner. The course
  // uses the centre (§d); the .cli reference images need (0, 1) (docs/reference/cs3451.md §A.4).
  glm::dvec2 pixelOffset{0.5, 0.5};
  // .cli: `right` is written for a square image and is stretched by width/height when the image is made, so
  // pixels stay square at any size and `fov` stays the vertical angle (docs/reference/cs3451.md §A.4 leaves this open).
  bool rightFollowsImage = false;
  // How a picture's point becomes a ray: one of projectionKinds() (scene/projection.hpp).
  const ProjectionKind* projection = &perspectiveProjection();
  // Radians, for the projections that take them; the direction's length as written (panoramic reads it).
  double angle = 0, verticalAngle = 0, directionLength = 1;
  std::shared_ptr<const MeshCamera> mesh;  // the mesh_camera's faces, with the mesh_camera projection
  // POV-Ray's camera `normal { … }` (manual, "Camera Ray Perturbation"): bends every eye ray's unit direction
  // as a surface's normal, read at (Us, Vs, 0), the picture's point as Camera::ray() names it (measured).
  std::shared_ptr<const Normal> normal;
  // POV-Ray's focal blur (manual, "Focal Blur"): on when aperture and maxSamples are both positive.
  struct FocalBlur {
    double aperture = 0;
    int minSamples = 0, maxSamples = 0;  // minSamples 0: POV-Ray's default, 4 below 7 samples and 7 from there
    glm::dvec3 focalPoint{0};
    double confidence = 0.9, variance = 1.0 / 128;
  } focalBlur;
  SourceLoc loc;  // the `camera` statement (POV) or the `fov` command (.cli) that set it, for messages
};

// A POV-Ray light's emitter kind (a spotlight or a cylinder light, scene/light_kind.hpp) and its values as
// written. At namespace scope: inside LightDesc, clang would take it as not default-constructible inside
// std::optional.
struct SpotDesc {
  glm::dvec3 pointAt{0};
  double radius = 30, falloff = 45, tightness = 0;  // a spotlight's degrees, degrees, exponent: POV-Ray's defaults
  const LightKind* kind = &spotlightKind();
};

// A POV-Ray area light (docs/povray-language.md, "Lights"): a size1 × size2 grid of points over the rectangle
// spanned by the two axes about the light's position, sampled for its shadows.
struct AreaDesc {
  glm::dvec3 axis1{0}, axis2{0};
  int size1 = 1, size2 = 1;
  int adaptive = -1;  // the subdivisions before the adaptive phase; -1 (no `adaptive`): every point
  bool jitter = false, circular = false, orient = false;
  bool illumination = false;  // area_illumination: each grid point lights from its own direction
};

struct LightDesc {
  glm::dvec3 position{0};
  Color color{1};
  // POV-Ray's light modifiers; a course light has none.
  std::optional<SpotDesc> spot;
  // An area light's grid, and a `parallel` light's point_at (its rays all along one direction), held by pointer:
  // the plain lights of a scene, a million in some, pay 16 bytes each for them.
  std::shared_ptr<const AreaDesc> area;
  std::shared_ptr<const glm::dvec3> parallelTo;
  double fadeDistance = 0, fadePower = 0;  // 0: no fading
  bool shadowless = false;
  bool mediaInteraction = true;  // `media_interaction off`: scattering media do not see it
  bool mediaAttenuation = false;  // `media_attenuation on`: the scene's fogs and media dim it on its way
};

// Pov is the course's subset of POV-Ray; PovRay the POV-Ray 3.7 language (docs/povray-language.md). Each
// language's shading rules are its Dialect (dialect.hpp).
enum class SceneLanguage { Pov, Cs3451, PovRay };

// An image the file itself asks for (.cli `write`), showing the scene as it stood at that command. A .cli file
// only adds lights and objects and changes its camera and background, so the scene then is the first `lights`
// lights and `objects` objects of the whole file's with that camera and background: a write keeps no copy.
struct WriteDesc {
  std::string path;  // as written, relative to the working directory
  SourceLoc loc;
  size_t lights = 0, objects = 0;
  CameraDesc camera;
  Color background{0};
};

// A text file a POV-Ray scene writes (#fopen … write or append, then #write). It is kept in memory while the scene
// is parsed, and only the image commands put it on disk, once the scene has parsed without error.
struct DataFileDesc {
  std::string path;  // where it goes: the scene's name inside the folder of the output image
  SourceLoc loc;     // the #fopen that first wrote it
  std::string text;  // the whole file: for append, what was there before and then what the scene wrote
};

struct SceneDesc {
  std::string file;
  SceneLanguage language = SceneLanguage::Pov;  // only reports that quote the file's own terms look at it
  CameraDesc camera;
  // Each light's projected_through object by the light's index (POV-Ray 3.7 manual, "Projected_Through"): the
  // light reaches a point only through it. Empty when no light has one: plain lights pay nothing for it.
  std::vector<std::shared_ptr<const ObjectDesc>> projectedThrough;
  std::vector<LightDesc> lights;
  std::vector<ObjectDesc> objects;
  Dialect dialect = Dialect::course();  // the language's shading rules, chosen by its parser
  Color background{0};
  std::optional<int> depthLimit;  // the scene's own (POV-Ray's max_trace_level), over its dialect's
  // POV-Ray's adc_bailout: a secondary ray whose weight in its pixel is below it is not traced; unset, the
  // tracer's own cutoff, which bounds what the skipped rays could add (render/tracer.cpp).
  std::optional<float> adcBailout;
  std::shared_ptr<const SkySphere> sky;  // seen where a ray leaves the scene, over the background
  std::vector<Fog> fogs;                 // each ray crosses them in order
  // Scene-level (atmospheric) `media`: around every ray as an outermost hollow interior (docs/povray-language.md).
  std::vector<Media> media;
  std::optional<RadiosityDesc> radiosity;  // POV-Ray's radiosity block: the ambient term gathered (docs/gi.md)
  std::vector<std::string> warnings;  // "file:line:col: warning: …", printed before any output
  // The images the file asks for, in order; empty for POV, whose `render` writes output.png.
  std::vector<WriteDesc> writes;
  std::vector<DataFileDesc> dataFiles;  // in the order they were first opened
  // The files besides itself whose contents the scene read (includes, images, #read data, fonts), as found,
  // in the order first found: what a tile of it depends on.
  std::vector<std::string> inputFiles;
  // The deepest secondary ray traced (the eye ray is depth 0): the scene's limit, or its dialect's.
  int maxDepth() const { return depthLimit.value_or(dialect.depthLimit()); }
};

// The scene `write` shows (see WriteDesc), without the writes.
SceneDesc sceneAt(const SceneDesc& whole, const WriteDesc& write);

}  // namespace rt
