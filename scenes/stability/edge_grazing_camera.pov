// Edge case (docs/accuracy.md): the camera 0.05 above a long plane, small spheres out to 400 units along it.
camera { location <0,0.05,0> up <0,0.15,0> right <0.2,0,0> look_at <0,0.05,-1> }
light_source { <20,30,10> color rgb <1,1,1> }
plane { <0,1,0>, 0 pigment { color rgb <0.6,0.6,0.5> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-0.8,0.3,-10>, 0.3 pigment { color rgb <1,0.3,0.2> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <0.5,0.25,-40>, 0.25 pigment { color rgb <0.2,0.8,0.3> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-2,0.4,-100>, 0.4 pigment { color rgb <0.3,0.4,1> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <3,0.3,-200>, 0.3 pigment { color rgb <1,1,0.3> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-5,0.5,-300>, 0.5 pigment { color rgb <1,0.5,1> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <8,0.4,-400>, 0.4 pigment { color rgb <0.5,1,1> } finish { ambient 0.2 diffuse 0.7 } }
