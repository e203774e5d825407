// clipped_by, inverse and the disc in CSG, to check against POV-Ray pixel by pixel:
//   raytrace render scenes/clip_inverse.pov 320 240 -o clip.png
//   povray +Iscenes/clip_inverse.pov +Oclip-ref.png +W320 +H240 -A -D -GA
// At 320x240 no pixel differs. The blue box less a clipped ball keeps nothing above the clip
// (docs/shapes.md, "clipped_by").
#version 3.7;
camera { location <0, 2.5, -6> look_at <0, 0, 0> angle 55 }
light_source { <4, 8, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
plane { y, -1.2 pigment { rgb 0.6 } }
sphere { <-2, 0, 0>, 1 clipped_by { box { <-3, -2, -2>, <-1.7, 2, 2> } } clipped_by { plane { z, 0.3 } } pigment { rgb <1, 0.3, 0.2> } }
intersection { sphere { 0, 1 } object { cylinder { <0, -2, 0>, <0, 2, 0>, 0.5 } inverse } pigment { rgb <0.3, 1, 0.3> } rotate 30*x }
difference { box { <1.2, -1, -1>, <3, 1, 1> } sphere { <2.1, 0.2, -0.5>, 0.8 clipped_by { plane { y, 0.3 } } } pigment { rgb <0.4, 0.5, 1> } }
disc { <0, 1.6, 0>, <0, 1, -0.5>, 0.8, 0.3 clipped_by { plane { x, 0.2 } } pigment { rgb <1, 1, 0> } }
