// default.pov: the scene the README renders. Three spheres of different finishes on a floor, a key light
// and a dimmer fill light.
camera {
  location <0, 1.5, 9>
  up       <0, 1, 0>
  right    <1.33333, 0, 0>
  look_at  <0, 0.5, 0>
}

light_source { <-8, 10, 8> color rgb <1.2, 1.2, 1.1> }
light_source { <9, 4, 6> color rgb <0.35, 0.4, 0.5> }

// a matte terracotta ball
sphere { <-2.3, 0, 0>, 1
  pigment { color rgb <0.85, 0.4, 0.25> }
  finish { ambient 0.12 diffuse 0.8 specular 0.1 roughness 0.3 }
}

// a polished blue ball, a little reflective
sphere { <0, 0.4, -1>, 1.4
  pigment { color rgb <0.2, 0.35, 0.85> }
  finish { ambient 0.1 diffuse 0.6 specular 0.6 roughness 0.05 reflection 0.25 }
}

// a glass ball in front
sphere { <2.2, -0.3, 0.8>, 0.7
  pigment { color rgbf <0.95, 0.95, 1.0, 0.85> }
  finish { ambient 0.05 diffuse 0.1 specular 0.8 roughness 0.02 reflection 0.1 ior 1.5 }
}

// the floor
plane { <0, 1, 0>, -1
  pigment { color rgb <0.75, 0.75, 0.7> }
  finish { ambient 0.15 diffuse 0.75 reflection 0.1 }
}
