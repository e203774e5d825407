// A glass sphere inside a mirror sphere: each hit on the glass spawns a reflected and a refracted ray, and the
// mirror sends every one back. The tree of one eye ray grows about 1.4 times a level; at --depth=64 it would
// have some 10^11 rays. The tracer follows only what can still change the pixel (tests/CMakeLists.txt).
camera { location <0,0,0.5> look_at <0,0,0> }
light_source { <0,0.5,0> color rgb <1,1,1> }
sphere { <0,0,0>, 10 pigment { color rgb <1,1,1> } finish { ambient 0.2 diffuse 0.4 reflection 1 } }
sphere { <0,0,-2>, 1 pigment { color rgbf <1,1,1,0.7> }
         finish { ambient 0.1 diffuse 0.2 reflection 0.3 refraction 1 ior 1.5 } }
