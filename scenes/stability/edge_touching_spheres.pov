// Edge case (docs/accuracy.md): small spheres (radius 0.05 to 0.1) that touch one another and the floor, the
// sphereflake's contacts in miniature; the fixed offset can start a shadow ray inside a neighbour.
camera { location <0,0.6,1.6> up <0,1,0> right <1.33333,0,0> look_at <0,0.1,0> }
light_source { <2,3,2> color rgb <1,1,1> }
light_source { <-3,1,1> color rgb <0.5,0.5,0.5> }
plane { <0,1,0>, 0 pigment { color rgb <0.8,0.8,0.7> } finish { ambient 0.1 diffuse 0.8 } }
sphere { <0,0.1,0>, 0.1 pigment { color rgb <0.9,0.3,0.2> } finish { ambient 0.1 diffuse 0.8 } }
sphere { <0.15,0.1,0>, 0.05 pigment { color rgb <0.3,0.9,0.2> } finish { ambient 0.1 diffuse 0.8 } }
sphere { <-0.15,0.1,0>, 0.05 pigment { color rgb <0.2,0.3,0.9> } finish { ambient 0.1 diffuse 0.8 } }
sphere { <0,0.25,0>, 0.05 pigment { color rgb <0.9,0.9,0.2> } finish { ambient 0.1 diffuse 0.8 } }
sphere { <0,0.1,0.15>, 0.05 pigment { color rgb <0.9,0.3,0.9> } finish { ambient 0.1 diffuse 0.8 } }
sphere { <0.3,0.07,0.1>, 0.07 pigment { color rgb <0.9,0.6,0.2> } finish { ambient 0.1 diffuse 0.8 } }
sphere { <0.44,0.07,0.1>, 0.07 pigment { color rgb <0.2,0.8,0.8> } finish { ambient 0.1 diffuse 0.8 } }
