#version 3.7;
camera { location <0, 1, -4> look_at 0 }
  lathe { linear_spline 2, <0, 0>, <1, 1> pigment { rgb 1 } }
