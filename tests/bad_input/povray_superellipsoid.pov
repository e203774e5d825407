#version 3.7;
camera { location <0, 1, -4> look_at 0 }
  superellipsoid { <1, 0.25> pigment { rgb 1 } }
