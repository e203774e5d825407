/* number forms POV-Ray reads */
camera { location <.5, -.001, 1.> up <+0, 1e-05, 1E+2> right <-0, 1, 0> look_at <1e3, 2.5e-3, -7> }
sphere { <1e300, -1e-300, 0>, 1e-30 pigment { rgb <0.94, .5, 1.> } finish { roughness 1e-9 ior 1.33 refraction 1 metallic 0.5 } }
