// A sliced quaternion julia_fractal and a hypercomplex one over a floor, to compare with POV-Ray's picture
// (160x120: 32 pixels of 19,200 off by more than 16/255):
//   raytrace render julia_fractal.pov 320 240   /   povray +Ijulia_fractal.pov +W320 +H240 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0, 0> angle 50 }
light_source { <-5, 8, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
julia_fractal { <-0.2, 0.6, 0.3, 0.1> quaternion sqr max_iteration 6 precision 30
  slice <0.3, 0, 0, 1>, 0.2 pigment { rgb <1, 0.7, 0.3> } finish { phong 0.5 } translate -1.3*x }
julia_fractal { <-0.745, 0, 0.113, 0.05> hypercomplex sqr max_iteration 8 precision 25
  pigment { rgb <0.4, 0.9, 0.5> } rotate <30, 20, 0> translate 1.3*x }
plane { y, -1.2 pigment { checker rgb 0.9, rgb 0.6 } }
