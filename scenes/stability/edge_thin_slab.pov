// Edge case (docs/accuracy.md): a glass slab 0.004 thick (twice the course's smallest feature) above a
// floor, and a mirror behind it, lit obliquely.
camera { location <0,3,6> up <0,1,0> right <1.33333,0,0> look_at <0,0.5,0> }
light_source { <-4,6,4> color rgb <1.2,1.2,1.2> }
plane { <0,1,0>, 0 pigment { color rgb <0.8,0.7,0.6> } finish { ambient 0.1 diffuse 0.8 } }
box { <-1.5,1,-1>, <1.5,1.004,1> pigment { color rgbf <0.9,0.95,1,0.8> } finish { ambient 0.05 diffuse 0.1 refraction 1 ior 1.5 } }
plane { <0,0,1>, -3 pigment { color rgb <0.9,0.9,0.9> } finish { ambient 0.02 diffuse 0.1 reflection 0.8 } }
sphere { <0.5,0.4,0>, 0.4 pigment { color rgb <0.9,0.3,0.2> } finish { ambient 0.1 diffuse 0.7 } }
