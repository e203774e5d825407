#version 3.7;
camera { location <0, 1, -4> look_at 0 }

#include "povray_include.inc"
sphere { 0, Size pigment { Colour } }
