#version 3.7;
#include "colors.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 1, 0> angle 50 }
light_source { <10, 10, -10> color White }
#declare R = seed(0);
#declare I = 0;
#while (I < 5)
  sphere { <rand(R)*4-2, 1, rand(R)*4>, 0.5 pigment { color Red } finish { phong 0.5 } }
  #declare I = I + 1;
#end
plane { y, 0 pigment { rgb <0.8, 0.8, 0.6> } }
#macro Add(A, B) A + B #end
#debug concat("Add: ", str(Add(1,2)*3, 0, 3), "\n")
