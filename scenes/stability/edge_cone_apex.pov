// Edge case (docs/accuracy.md): pointed cones seen close to their apexes, where the side's quadratic loses
// its digits in float.
camera { location <0,0.5,8> up <0,1,0> right <1.33333,0,0> look_at <0,0.5,0> }
light_source { <5,8,10> color rgb <1,1,1> }
cone { <-1.5,-1,0>, 1, <-1.5,2,0>, 0 pigment { color rgb <0.9,0.4,0.2> } finish { ambient 0.2 diffuse 0.7 specular 0.4 roughness 0.05 } }
cone { <1.5,2,0>, 0.8, <1.5,-1,0>, 0 pigment { color rgb <0.2,0.5,0.9> } finish { ambient 0.2 diffuse 0.7 specular 0.4 roughness 0.05 } }
cone { <0,-1,-2>, 0.6, <0,3,-2>, 0 pigment { color rgb <0.3,0.9,0.3> } finish { ambient 0.2 diffuse 0.7 } }
plane { <0,1,0>, -1 pigment { color rgb <0.7,0.7,0.7> } finish { ambient 0.2 diffuse 0.6 } }
