// Showcase: POV-Ray's textures on a row of objects: granite, marble, wood, bozo and agate through colour maps,
// a bumped and a rippled normal, an image_map of resources/default.png and a two-layer texture.
// The picture in resources/textures.png was made, from this folder, with
//   raytrace render textures.pov 640 480 -o ../resources/textures.png
// (POV-Ray: povray +Itextures.pov +W640 +H480 -A; docs/povray-language.md, "Showcase scenes").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4.2, -9> look_at <0, 0.6, 0> angle 52 }
light_source { <-6, 10, -8> rgb 1 }
light_source { <7, 6, -5> rgb 0.35 shadowless }
background { rgb <0.55, 0.65, 0.8> }

// The floor: a rippled, tiled wood.
plane { y, 0
  texture {
    pigment { wood turbulence 0.15 scale 0.4 rotate 90*y
      color_map { [0 rgb <0.65, 0.42, 0.22>] [0.6 rgb <0.5, 0.3, 0.14>] [1 rgb <0.35, 0.2, 0.08>] } }
    normal { ripples 0.25 frequency 4 scale 3 }
    finish { phong 0.3 }
  }
}

// Back row: granite, marble, agate.
sphere { <-2.6, 1, 1.6>, 1
  pigment { granite scale 0.8
    color_map { [0 rgb 0.9] [0.4 rgb <0.6, 0.55, 0.5>] [0.7 rgb <0.3, 0.25, 0.25>] [1 rgb 0.05] } }
  finish { phong 0.6 phong_size 60 }
}
sphere { <0, 1, 1.6>, 1
  pigment { marble turbulence 0.9 scale 0.7
    color_map { [0 rgb 0.95] [0.75 rgb <0.85, 0.85, 0.9>] [0.9 rgb <0.3, 0.35, 0.5>] [1 rgb 0.1] } }
  finish { specular 0.5 roughness 0.02 reflection 0.05 }
}
sphere { <2.6, 1, 1.6>, 1
  pigment { agate agate_turb 0.6 scale 0.9
    color_map { [0 rgb <0.5, 0.15, 0.05>] [0.5 rgb <0.95, 0.7, 0.4>] [1 rgb <0.3, 0.1, 0.05>] } }
  finish { phong 0.4 }
}

// Front row: bozo with bumps, a picture on a box face, and a layered texture.
sphere { <-2.4, 0.75, -1.2>, 0.75
  pigment { bozo scale 0.3
    color_map { [0 rgb <0.2, 0.4, 0.9>] [0.5 rgb <0.9, 0.9, 0.3>] [1 rgb <0.9, 0.2, 0.2>] } }
  normal { bumps 0.6 scale 0.15 }
  finish { phong 0.5 }
}
box { <-0.8, 0, -0.1>, <0.8, 1.2, 0.1>
  // image_map covers the unit square of x and y: scaled and moved onto the box's front face.
  pigment { image_map { png "../resources/default.png" } scale <1.6, 1.2, 1> translate <-0.8, 0, 0> }
  finish { ambient 0.2 diffuse 0.8 }
  rotate -15*y translate <0, 0, -1.2>
}
#declare Stripes = texture {
  pigment { gradient y scale 0.3 color_map { [0 rgbf <1, 1, 1, 1>] [0.5 rgbf <1, 1, 1, 1>]
                                             [0.5 rgb <0.1, 0.3, 0.1>] [1 rgb <0.1, 0.3, 0.1>] } }
  finish { phong 0.7 }
}
cylinder { <2.4, 0, -1.2>, <2.4, 1.5, -1.2>, 0.6
  texture { pigment { checker rgb <0.95, 0.8, 0.2>, rgb <0.8, 0.3, 0.1> scale 0.25 } }
  texture { Stripes rotate 25*z }
}
