#version 3.7;
camera { location <0, 1, -4> look_at 0 }
  sphere_sweep { linear_spline 2, <0, 0, 0>, 0.5, <1, 1, 0>, 0.5 pigment { rgb 1 } }
