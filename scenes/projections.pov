// The fisheye, omnimax and panoramic cameras against POV-Ray: render with Declare=Kind=0, 1 or 2
// (raytrace: -D Kind=…). A room of coloured walls, a checker floor and spheres all round the camera.
#version 3.7;
global_settings { assumed_gamma 1 }
#ifndef (Kind) #declare Kind = 0; #end
camera {
  #switch (Kind)
  #case (0) fisheye angle 200 #break
  #case (1) omnimax #break
  #case (2) panoramic #break
  #end
  location <0, 1, 0> look_at <1, 1.3, 4>
}
light_source { <3, 6, -2> rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.2, 0.3, 0.5> } }
plane { y, 6 pigment { rgb <0.8, 0.7, 0.6> } }
box { <-8, -1, -8>, <8, 7, 8> inverse pigment { gradient x color_map { [0 rgb <0.8, 0.2, 0.2>] [1 rgb <0.2, 0.8, 0.3>] } scale 16 translate -8*x } }
#declare I = 0;
#while (I < 8)
  sphere { <4 * sin(I * pi / 4), 1, 4 * cos(I * pi / 4)>, 0.8
    pigment { rgb <mod(I, 2), mod(div(I, 2), 2), mod(div(I, 4), 2)> * 0.7 + 0.2 } finish { phong 0.6 } }
  #declare I = I + 1;
#end
