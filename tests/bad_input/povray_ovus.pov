#version 3.7;
camera { location <0, 1, -4> look_at 0 }
  ovus { 1, 0.5 pigment { rgb 1 } }
