// The text shape with flat colours, to check where the letters fall against POV-Ray pixel by pixel:
//   raytrace render scenes/text.pov 320 240 -o text.png
//   povray +Iscenes/text.pov +Otext-ref.png +W320 +H240 -A -D -GA +L/usr/share/povray-3.7/include
// (fonts from Debian's fonts-povray). At 320x240, 4 of its 76800 pixels differ, on letters' edges.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <1.85, 0.9, -4.4> look_at <1.85, 0.9, 0> }
background { rgb <0.1, 0.2, 0.4> }
#declare Flat = finish { ambient 1 diffuse 0 }
// Kerning (AV), a bowl with a hole (O), a descender (g), and an offset between letters.
text { ttf "timrom.ttf" "AVOgW&j" 0.3, <0.05, 0.03, 0> pigment { rgb <1, 0.8, 0.2> } finish { Flat } }
// A font named without .ttf, moved and turned.
text { ttf "cyrvetic" "Hello, I'm 3-D" 0.2, 0 pigment { rgb <0.3, 1, 0.4> } finish { Flat } scale 0.6 rotate 5*z translate <-0.2, 1, 0> }
// POV-Ray's built-in fonts by number: the logo is the letter P of the first.
text { internal 0 "P" 0.1, 0 pigment { rgb 1 } finish { Flat } scale 0.5 translate <2.8, 1.7, 0> }
text { internal 3 "crystal" 0.1, 0 pigment { rgb <1, 0.4, 0.4> } finish { Flat } scale 0.4 translate <0.2, 1.8, 0> }
