#!/usr/bin/env bash
# raytrace convert on real models of Debian's assimp-testmodels: the textured spider (an OBJ of quads and
# triangles) converted, read by a scene that maps its texture by the file's uvs and rendered, one pixel
# compared with real POV-Ray's render of the same include; the PLY cube with normals and uvs read back.
# usage: tests/convert_model.sh <raytrace> <work folder>
set -euo pipefail
bin=$1 work=$2 models=/usr/share/assimp/models
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "$1"; exit 1; }
"$bin" convert "$models/OBJ/spider.obj" spider.inc
cp "$models/OBJ/SpiderTex.jpg" .
cat >spider.pov <<'SCENE'
#version 3.7;
#include "spider.inc"
camera { location <0, 60, -250> look_at <0, 5, 0> angle 40 }
light_source { <100, 200, -200> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
object { Spider texture { uv_mapping pigment { image_map { jpeg "SpiderTex.jpg" } } finish { ambient 0.2 } } }
SCENE
# The OBJ's 1368 triangles once its polygons are fanned.
"$bin" sceneinfo spider.pov | grep -qx -- "- Triangles: 1368" || fail "spider.inc has not 1368 triangles"
# The middle pixel of an 80 x 60 render (y counted upward) is on the spider's textured back: POV-Ray 3.7 gives
# it (62, 56, 43); within 1 of each.
colour=$("$bin" pixelcolor spider.pov 80 60 40 30 | grep '^Color:')
echo "$colour" | awk -F'[(), ]+' '{ d = 0; split("62 56 43", p, " ");
  for (i = 1; i <= 3; i++) { e = $(i + 1) - p[i]; if (e < -1 || e > 1) d = 1 } exit d }' ||
  fail "the spider's middle pixel is $colour, POV-Ray's (62, 56, 43)"
"$bin" render spider.pov 80 60 -o spider.png
[[ -s spider.png ]] || fail "no spider.png"
"$bin" convert "$models/PLY/cube_uv.ply" cube.inc --name Cube
printf '#version 3.7;\n#include "cube.inc"\nobject { Cube pigment { rgb 1 } }\n' >cube.pov
"$bin" sceneinfo cube.pov | grep -qx -- "- Triangles: 12" || fail "cube.inc has not 12 triangles"
grep -q '^  uv_indices {$' cube.inc && grep -q '^  normal_indices {$' cube.inc || fail "cube.inc lost its normals or uvs"
