// Edge case (docs/accuracy.md): a glass sphere framed tightly, in front of a striped wall, so that much of
// the picture is its silhouette, where refracted rays enter at grazing angles.
camera { location <0,0,6> up <0,1.2,0> right <1.6,0,0> look_at <0,0,0> }
light_source { <4,6,8> color rgb <1,1,1> }
sphere { <0,0,0>, 1 pigment { color rgbf <0.95,0.95,0.95,0.9> } finish { ambient 0.02 diffuse 0.1 specular 0.6 roughness 0.02 refraction 1 ior 1.5 } }
plane { <0,0,1>, -6 pigment { color rgb <0.9,0.9,0.9> } finish { ambient 0.3 diffuse 0.6 } }
box { <-3,-0.9,-5.9>, <3,-0.7,-5.8> pigment { color rgb <0.1,0.1,0.8> } finish { ambient 0.3 diffuse 0.6 } }
box { <-3,-0.3,-5.9>, <3,-0.1,-5.8> pigment { color rgb <0.8,0.1,0.1> } finish { ambient 0.3 diffuse 0.6 } }
box { <-3,0.3,-5.9>, <3,0.5,-5.8> pigment { color rgb <0.1,0.7,0.1> } finish { ambient 0.3 diffuse 0.6 } }
box { <-0.6,-3,-5.95>, <-0.4,3,-5.9> pigment { color rgb <0.1,0.1,0.1> } finish { ambient 0.3 diffuse 0.6 } }
box { <0.4,-3,-5.95>, <0.6,3,-5.9> pigment { color rgb <0.1,0.1,0.1> } finish { ambient 0.3 diffuse 0.6 } }
