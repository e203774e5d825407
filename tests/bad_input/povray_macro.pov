#version 3.7;
#macro Tree(H)
  sphere { 0, H pigment { Bad } }
#end
camera { location <0, 1, -4> look_at 0 }
Tree(1)
