// A glass sphere, a mirror sphere and a triangle on a floor, lit by two lights: every ray kind of
// Programs 2 and 3 (shadow, reflection, refraction in and out, total internal reflection) in one scene.
camera {
  location <0, 1, 8>
  up <0, 1, 0>
  right <1.33333, 0, 0>
  look_at <0, 0, 0>
}

light_source { <-6, 8, 6> color rgb <1.2, 1.2, 1.2> }
light_source { <5, 4, 3> color rgb <0.4, 0.4, 0.5> }

// glass: mostly transmitted, dense enough for total internal reflection near its rim
sphere { <-1.2, 0, 0>, 1
  pigment { color rgbf <0.9, 1.0, 0.9, 0.8> }
  finish { ambient 0.1 diffuse 0.3 specular 0.6 roughness 0.05 ior 1.6 }
}

// mirror
sphere { <1.3, 0.2, -1>, 1.2
  pigment { color rgb <0.9, 0.8, 0.6> }
  finish { ambient 0.1 diffuse 0.3 specular 0.4 roughness 0.1 reflection 0.7 }
}

triangle { <-3, -1, -3>, <3, -1, -3>, <0, 2.5, -4>
  pigment { color rgb <0.3, 0.6, 0.3> }
  finish { ambient 0.2 diffuse 0.7 }
}

plane { <0, 1, 0>, -1
  pigment { color rgb <0.6, 0.6, 0.7> }
  finish { ambient 0.2 diffuse 0.6 reflection 0.1 }
}
