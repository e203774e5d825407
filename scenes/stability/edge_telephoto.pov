// Edge case (docs/accuracy.md): a telephoto view (1.5e-4 rad per pixel) of spheres of radius 0.2 to 1 at
// 60 to 120 units, each lit and shadowing a floor.
camera { location <0,3,60> up <0,0.075,0> right <0.1,0,0> look_at <0,0.5,-30> }
light_source { <30,40,40> color rgb <1.2,1.2,1.2> }
plane { <0,1,0>, 0 pigment { color rgb <0.7,0.7,0.6> } finish { ambient 0.15 diffuse 0.8 } }
sphere { <0,0.5,0>, 0.5 pigment { color rgb <0.9,0.2,0.2> } finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 0.05 } }
sphere { <1.5,0.3,-10>, 0.3 pigment { color rgb <0.2,0.9,0.2> } finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 0.05 } }
sphere { <-2,1,-30>, 1 pigment { color rgb <0.2,0.3,0.9> } finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 0.05 } }
sphere { <2.5,0.2,-40>, 0.2 pigment { color rgb <0.9,0.9,0.2> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <-0.5,0.8,-60>, 0.8 pigment { color rgb <0.9,0.5,0.9> } finish { ambient 0.1 diffuse 0.7 reflection 0.3 } }
