// Open cylinders and cones, no_image and no_reflection, and a height field of a function: compared with
// POV-Ray 3.7's picture of the same scene (docs/shapes.md).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 12, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.45> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 } }
// A mirror behind: what it shows differs from what the camera sees.
box { <-5, 0, 3>, <5, 4, 3.2> pigment { rgb 0.2 } finish { reflection 0.8 } }
cylinder { <-3, 0, 0>, <-3, 2, 0>, 0.8 open pigment { rgb <1, 0.5, 0.2> } rotate -20 * x translate <0, 0.3, 0> }
cone { <-0.8, 0, 0>, 0.9, <-0.8, 1.8, 0>, 0.4 open pigment { rgb <0.3, 0.8, 0.3> } }
sphere { <1.2, 0.7, -1>, 0.7 no_image pigment { rgb <0.9, 0.2, 0.2> } }
sphere { <1.2, 0.7, 1>, 0.7 no_reflection pigment { rgb <0.2, 0.3, 0.9> } }
height_field {
  function 40, 40 { 0.5 + 0.4 * sin(6 * x) * cos(5 * y) }
  smooth
  pigment { rgb <0.9, 0.85, 0.6> }
  translate <-0.5, 0, -0.5> scale <2, 1, 2> translate <3, 0, -0.5>
}
