// Stability scene S2 (stability.md §3): spheres of radius 1e-2 at distances 1e3 to 1e4 through a narrow
// camera (1e-6 rad per pixel at 160 px: radii of 10 to 1 pixels), R = 1e6: float loses them, double keeps
// them round.
camera {
  location <0, 0, 0>
  up <0, 0.00012, 0>
  right <0.00016, 0, 0>
  look_at <0, 0, -1>
}

light_source { <0, 1000, 1000> color rgb <1, 1, 1> }

sphere { <-0.04, 0.02, -1000>, 0.01
  pigment { color rgb <1.0, 0.3, 0.2> }
  finish { ambient 0.2 diffuse 0.8 }
}
sphere { <0.06, -0.03, -2000>, 0.01
  pigment { color rgb <0.3, 1.0, 0.2> }
  finish { ambient 0.2 diffuse 0.8 }
}
sphere { <-0.2, -0.15, -5000>, 0.01
  pigment { color rgb <0.2, 0.4, 1.0> }
  finish { ambient 0.2 diffuse 0.8 }
}
sphere { <0.5, 0.35, -10000>, 0.01
  pigment { color rgb <1.0, 1.0, 0.3> }
  finish { ambient 0.2 diffuse 0.8 }
}
