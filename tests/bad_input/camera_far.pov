camera { location <-1e308,0,0> look_at <1e308,0,0> up <0,1,0> right <0,0,1> }
sphere { <0,0,-5>, 1 pigment { color rgb <1,0,0> } }
