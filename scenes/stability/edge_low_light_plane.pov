// Edge case (docs/accuracy.md): a light 1.5° above a long plane: every shadow on it is stretched 38 times,
// and the fixed offset moves each shadow ray's origin along it.
camera { location <0,2,10> up <0,1,0> right <1.33333,0,0> look_at <0,0.5,-10> }
light_source { <80,2.1,-30> color rgb <4,4,4> }
plane { <0,1,0>, 0 pigment { color rgb <0.8,0.8,0.8> } finish { ambient 0.1 diffuse 0.9 } }
sphere { <-1,0.5,0>, 0.5 pigment { color rgb <0.9,0.3,0.2> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <1.5,0.7,-8>, 0.7 pigment { color rgb <0.3,0.8,0.3> } finish { ambient 0.1 diffuse 0.7 } }
cylinder { <-3,0,-15>, <-3,2,-15>, 0.2 pigment { color rgb <0.3,0.3,0.9> } finish { ambient 0.1 diffuse 0.7 } }
box { <2,0,-25>, <3,1,-24> pigment { color rgb <0.9,0.9,0.3> } finish { ambient 0.1 diffuse 0.7 } }
