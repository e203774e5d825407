// Stability scene S3 (stability.md §3): four glass spheres between two facing mirrors: deep trees of
// refraction and reflection, where the recursion depth and the offsets of entering rays decide the picture.
camera {
  location <0, 2, 10>
  up <0, 1, 0>
  right <1.33333, 0, 0>
  look_at <0, 0.8, 0>
}

light_source { <3, 8, 6> color rgb <1.3, 1.3, 1.3> }

sphere { <-2.4, 0.8, 0>, 0.8
  pigment { color rgbf <0.95, 1.0, 0.95, 0.9> }
  finish { ambient 0.05 diffuse 0.1 specular 0.7 roughness 0.03 ior 1.5 }
}
sphere { <-0.8, 0.8, -1>, 0.8
  pigment { color rgbf <1.0, 0.95, 0.95, 0.9> }
  finish { ambient 0.05 diffuse 0.1 specular 0.7 roughness 0.03 ior 1.5 }
}
sphere { <0.8, 0.8, 0>, 0.8
  pigment { color rgbf <0.95, 0.95, 1.0, 0.9> }
  finish { ambient 0.05 diffuse 0.1 specular 0.7 roughness 0.03 ior 2.42 }
}
sphere { <2.4, 0.8, -1>, 0.8
  pigment { color rgbf <1.0, 1.0, 0.9, 0.9> }
  finish { ambient 0.05 diffuse 0.1 specular 0.7 roughness 0.03 ior 1.5 }
}

plane { <0, 1, 0>, 0
  pigment { color rgb <0.8, 0.5, 0.3> }
  finish { ambient 0.15 diffuse 0.8 }
}
plane { <1, 0, 0>, -5
  pigment { color rgb <0.95, 0.95, 0.95> }
  finish { ambient 0.02 diffuse 0.05 reflection 0.9 }
}
plane { <-1, 0, 0>, -5
  pigment { color rgb <0.95, 0.95, 0.95> }
  finish { ambient 0.02 diffuse 0.05 reflection 0.9 }
}
