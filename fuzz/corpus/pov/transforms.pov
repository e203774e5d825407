camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }
sphere { <0,0,0>, 1 scale <1e-8, 1, 1e8> rotate <90, 45, 30> translate <0, 0, -1e6> pigment { rgb <1,1,1> } }
plane { <1e-300, 0, 0>, 1e300 pigment { rgb <1,1,1> } rotate <0,0,90> }
