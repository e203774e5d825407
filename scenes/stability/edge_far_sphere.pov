// Edge case (docs/accuracy.md): a sphere of radius 0.1 at 300 units through a narrow camera (2e-5 rad per
// pixel at 640 × 480): R = 3000, where the textbook quadratic in float loses its outline.
camera { location <0,0,0> up <0,0.01,0> right <0.013333,0,0> look_at <0,0,-1> }
light_source { <0,100,100> color rgb <1,1,1> }
sphere { <0.3,0.2,-300>, 0.1 pigment { color rgb <1,0.2,0.2> } finish { ambient 0.3 diffuse 0.7 } }
