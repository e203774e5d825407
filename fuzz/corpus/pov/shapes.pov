camera { location <0,0,5> up <0,1,0> right <1,0,0> look_at <0,0,0> }
light_source { <5,5,5> colour rgb <1,1,1> }
triangle { <0,0,0>, <1,0,0>, <0,1,0> pigment { rgb <1,0,0> } }
box { <-1,-1,-1>, <1,1,1> pigment { color rgb <0,1,0> } rotate <0,45,0> scale 0.5 }
cone { <0,0,0>, 1, <0,2,0>, 0 pigment { color rgb <0,0,1> } }
cylinder { <0,0,0>, <0,0,1>, 0.5 pigment { color rgb <1,1,0> } scale <1,2,3> }
