// The camera sits inside a block of glass (everything below the plane y = 0) and looks up at the surface at a
// grazing angle, beyond the critical angle asin(1/1.5) = 41.8°: total internal reflection sends the
// transmitted share down onto the floor. Near the image bottom the rays are steep enough to leave the glass.
camera {
  location <0, -1, 5>
  up <0, 1, 0>
  right <1.33333, 0, 0>
  look_at <0, 0, 0>
}

light_source { <2, 10, 5> color rgb <1, 1, 1> }

plane { <0, 1, 0>, 0
  pigment { color rgbf <0.8, 0.9, 1.0, 0.9> }
  finish { ambient 0.1 diffuse 0.2 ior 1.5 }
}

plane { <0, 1, 0>, -3
  pigment { color rgb <0.8, 0.5, 0.3> }
  finish { ambient 0.3 diffuse 0.7 }
}

sphere { <0, 3, -6>, 2
  pigment { color rgb <0.2, 0.4, 0.9> }
  finish { ambient 0.2 diffuse 0.8 }
}
