// two spheres, a plane and a light
camera {
  location <0, 0, 14>
  up <0, 1, 0>
  right <1.33333, 0, 0>
  look_at <0, 0, 0>
}
light_source { <-100, 100, 100> color rgb <1.5, 1.5, 1.5> }
sphere { <0, 1, 0>, 2
  pigment { color rgb <1, 0, 1> }
  finish { ambient 0.2 diffuse 0.4 specular 0.5 roughness 0.05 }
  translate <1, 0, 0>
}
plane { <0, 1, 0>, -4
  pigment { color rgbf <0.2, 0.2, 0.8, 0.5> }
  finish { ambient 0.4 diffuse 0.8 reflection 0.5 }
}
