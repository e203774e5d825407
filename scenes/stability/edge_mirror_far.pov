// Edge case (docs/accuracy.md): a mirror floor reflecting small spheres 50 to 200 units away, through a
// camera of 4e-4 rad per pixel.
camera { location <0,1,5> up <0,0.2,0> right <0.26667,0,0> look_at <0,0.3,-100> }
light_source { <10,50,20> color rgb <1,1,1> }
plane { <0,1,0>, 0 pigment { color rgb <0.3,0.3,0.3> } finish { ambient 0.05 diffuse 0.2 reflection 0.7 } }
sphere { <-1,1,-50>, 0.3 pigment { color rgb <0.9,0.3,0.2> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <2,2,-100>, 0.4 pigment { color rgb <0.3,0.9,0.2> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-4,3,-150>, 0.5 pigment { color rgb <0.2,0.3,0.9> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <5,2,-200>, 0.5 pigment { color rgb <0.9,0.9,0.2> } finish { ambient 0.2 diffuse 0.7 } }
