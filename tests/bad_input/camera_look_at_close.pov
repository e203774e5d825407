camera { location <0,0,0> look_at <1e-300,0,0> }
sphere { <0,0,-5>, 1 pigment { color rgb <1,0,0> } }
