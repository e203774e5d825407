// Edge case (docs/accuracy.md): a light 2.4° above the floor beside two low boxes, so the shadow rays from the
// floor graze the boxes' top edges, and the far ends of the shadows (5 units away, in view) depend on which
// side of an edge each one passes.
camera { location <0,4,9> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }
light_source { <-30,1.25,-6> color rgb <4,4,4> }
light_source { <5,10,10> color rgb <0.2,0.2,0.2> }
plane { <0,1,0>, 0 pigment { color rgb <0.8,0.8,0.7> } finish { ambient 0.1 diffuse 0.8 } }
box { <-4,0,-2>, <-3,0.2,-1> pigment { color rgb <0.8,0.3,0.2> } finish { ambient 0.1 diffuse 0.7 } }
box { <-4.5,0,0.5>, <-4,0.3,1> pigment { color rgb <0.2,0.4,0.8> } finish { ambient 0.1 diffuse 0.7 } }
