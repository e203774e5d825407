#version 3.7;
camera { location <0, 1, -4> look_at 0 }
  text { ttf "nofont.ttf" "Hello" 0.5, 0 pigment { rgb 1 } }
