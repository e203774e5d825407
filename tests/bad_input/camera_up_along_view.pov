camera { location <0,10,0> look_at <0,0,0> up <0,1,0> right <1.33,0,0> }
sphere { <0,0,0>, 1 pigment { color rgb <1,0,0> } }
