// A sphere of radius 1e-320, a subnormal double whose square is 0: the eye ray through pixel (1, 1) of a 3x3
// image passes exactly through its centre, where no normal can be found. It is missed (printrays printed a NaN
// point and normal, and Waechter-Binder offsets cast the NaN to an integer): tests/golden/tiny_sphere_printrays.txt.
camera { location <0,0,5> look_at <0,0,0> }
light_source { <5,5,5> color rgb <1,1,1> }
sphere { <0,0,0>, 1e-320 pigment { color rgb <1,0,0> } finish { reflection 0.5 } }
