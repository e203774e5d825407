// Edge case (docs/accuracy.md): a low light behind a box, so the shadow rays from the floor graze the box's
// top edge and the long shadow's outline depends on which side of the edge each one passes.
camera { location <0,4,9> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }
light_source { <-30,2.2,-6> color rgb <1.3,1.3,1.3> }
light_source { <5,10,10> color rgb <0.2,0.2,0.2> }
plane { <0,1,0>, 0 pigment { color rgb <0.8,0.8,0.7> } finish { ambient 0.1 diffuse 0.8 } }
box { <-4,0,-2>, <-3,1,-1> pigment { color rgb <0.8,0.3,0.2> } finish { ambient 0.1 diffuse 0.7 } }
box { <-5,0,0.5>, <-4.5,1.5,1> pigment { color rgb <0.2,0.4,0.8> } finish { ambient 0.1 diffuse 0.7 } }
