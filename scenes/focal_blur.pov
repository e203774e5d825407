// Showcase: depth of field. A row of spheres recedes from the camera; the lens is focused on the third one,
// so the nearer and farther spheres and the checkered floor blur with their distance from it.
// The picture in resources/focal_blur.png was made, from this folder, with
//   raytrace render focal_blur.pov 640 480 -o ../resources/focal_blur.png
// (POV-Ray: povray +Ifocal_blur.pov +W640 +H480 -A; docs/povray-language.md, "Showcase scenes").
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Focus = <-0.3, 0.5, 1.5>;
camera {
  location <0, 1.5, -5> look_at <0.2, 0.5, 3> angle 55
  aperture 0.6            // the lens's width: more is a shallower depth of field
  blur_samples 10, 60     // at least 10 rays a pixel, at most 60
  confidence 0.95 variance 1/2000  // stop sampling once the pixel's colour is this sure
  focal_point Focus       // the sharp plane passes through the third sphere's centre
}
light_source { <-8, 12, -6> rgb 1 }
light_source { <6, 8, -10> rgb 0.3 shadowless }
background { rgb <0.5, 0.6, 0.75> }
plane { y, 0 pigment { checker rgb 0.85, rgb <0.25, 0.3, 0.4> scale 0.7 } finish { diffuse 0.8 } }
#declare Colours = array[7] { <0.9, 0.2, 0.15>, <0.95, 0.6, 0.1>, <0.9, 0.9, 0.2>, <0.3, 0.8, 0.3>,
                              <0.2, 0.6, 0.9>, <0.35, 0.3, 0.85>, <0.75, 0.3, 0.8> }
#declare I = 0;
#while (I < 7)
  sphere { <-1.5 + 0.6*I, 0.5, -1.5 + 1.5*I>, 0.5
    pigment { rgb Colours[I] } finish { phong 0.6 phong_size 40 reflection 0.05 } }
  #declare I = I + 1;
#end
