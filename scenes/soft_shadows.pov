// Showcase: soft shadows. A round area light (adaptive sampling, jittered points, circular and oriented)
// casts penumbras that widen with the distance from object to floor; a spotlight adds a hard-edged pool.
// The picture in resources/soft_shadows.png was made, from this folder, with
//   raytrace render soft_shadows.pov 640 480 -o ../resources/soft_shadows.png
// (POV-Ray: povray +Isoft_shadows.pov +W640 +H480 -A; docs/povray-language.md, "Showcase scenes").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -8> look_at <0, 0.8, 0> angle 50 }
background { rgb <0.1, 0.12, 0.16> }

// A 1.6-unit disc of 9x9 points: adaptive 1 samples the grid's corners first and subdivides only where
// they disagree, jitter spreads the points within their cells, circular rounds the square grid into a disc
// and orient turns that disc to face every point it lights.
light_source { <-3, 7, -2> rgb 0.85
  area_light <1.6, 0, 0>, <0, 0, 1.6>, 9, 9
  adaptive 1 jitter circular orient
}
// The spotlight: full light within 9 degrees of its axis, fading out to 12.
light_source { <5, 6, -3> rgb <1, 0.85, 0.6>
  spotlight point_at <2.6, 0, -0.6> radius 9 falloff 12 tightness 5
}

plane { y, 0 pigment { rgb 0.8 } }
sphere { <-1.6, 1, 0>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
box { <-0.6, 0, -0.6>, <0.6, 1.8, 0.6> rotate 30*y translate <1.2, 0, 1.2> pigment { rgb <0.3, 0.6, 0.9> } }
// A torus held above the floor: its shadow's edge is the softest of the three.
torus { 0.6, 0.15 rotate 25*x translate <-0.2, 1.7, -2.2> pigment { rgb <0.95, 0.8, 0.2> } finish { phong 0.5 } }
cylinder { <2.8, 0, -0.4>, <2.8, 0.5, -0.4>, 0.3 pigment { rgb <0.4, 0.85, 0.4> } }
