// Stability scene S4 (stability.md §3): S1 (s1_grazing.pov) with camera, lights and objects moved by
// <1e4, 1e4, 1e4>. In double it renders like S1; in float ulp(1e4) = 1e-3 starts to show.
camera {
  location <10000, 10003, 10012>
  up <0, 1, 0>
  right <1.33333, 0, 0>
  look_at <10000, 10001, 10000>
}

// elevation atan(3.5 / 40) = 5.0° seen from the spheres
light_source { <10040, 10003.5, 9998> color rgb <1.5, 1.5, 1.5> }
light_source { <9996, 10010, 10010> color rgb <0.3, 0.3, 0.3> }

sphere { <9997.8, 10001, 10000>, 1
  pigment { color rgb <0.9, 0.3, 0.2> }
  finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 0.05 }
}
sphere { <10000, 10001, 9998.5>, 1
  pigment { color rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.05 diffuse 0.2 specular 0.8 roughness 0.02 reflection 0.8 }
}
sphere { <10002.2, 10001, 10000>, 1
  pigment { color rgb <0.2, 0.4, 0.9> }
  finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 0.05 }
}

plane { <0, 1, 0>, 10000
  pigment { color rgb <0.7, 0.7, 0.6> }
  finish { ambient 0.15 diffuse 0.8 }
}

// the two mirrors, facing each other across the scene
plane { <1, 0, 0>, 9994
  pigment { color rgb <0.95, 0.95, 0.95> }
  finish { ambient 0.02 diffuse 0.05 reflection 0.85 }
}
plane { <-1, 0, 0>, -10006
  pigment { color rgb <0.95, 0.95, 0.95> }
  finish { ambient 0.02 diffuse 0.05 reflection 0.85 }
}
