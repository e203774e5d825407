camera { location <0,0,5> look_at <0,0,0> }
sphere { <0,0,0>, 1 pigment { color rgb <1,0,0,0,1> } }
