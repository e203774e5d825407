// basic.pov: spheres and planes for the Program 1 checks (sceneinfo, pixelray, firsthit, raycast).
// Key firsthit values at 301x201, by hand (course camera: d = Us*right + Vs*up + l, Us = (x+0.5)/w - 0.5):
//   (150, 100): Us = Vs = 0, d = (0, 0, -1): the red sphere at t = 10 - 2 = 8.
//   (0, 100):   Us = -0.498339, d = (-0.747508, 0, -1), |d| = 1.248506: the wall x = -8 at
//               t = 8 / 0.747508 * 1.248506 = 13.3618.
//   (150, 10):  Vs = -0.447761, |d| = 1.095669: the floor y = -2 at t = 2 / 0.447761 * 1.095669 = 4.8940.
//   (300, 200): d ~ (0.7475, 0.4975, -1) rises away from every object: No Hit.
camera {
  location <0, 0, 10>
  up       <0, 1, 0>
  right    <1.5, 0, 0>
  look_at  <0, 0, 0>
}

light_source { <-10, 10, 10> color rgb <1, 1, 1> }
light_source { <10, 5, 10> color rgb <0.5, 0.5, 0.6> }

// red, in the middle
sphere { <0, 0, 0>, 2
  pigment { color rgb <0.9, 0.2, 0.2> }
  finish { ambient 0.2 diffuse 0.6 specular 0.4 roughness 0.1 }
}

// green glass, behind and to the right
sphere { <3, 1, -4>, 1.5
  pigment { color rgbf <0.2, 0.8, 0.3, 0.5> }
  finish { ambient 0.1 diffuse 0.7 }
}

// blue mirror, low on the left
sphere { <-3.5, -1, -2>, 1
  pigment { color rgb <0.2, 0.3, 0.9> }
  finish { diffuse 0.8 ambient 0.15 reflection 0.3 }
}

// the floor, y = -2
plane { <0, 1, 0>, -2
  pigment { color rgb <0.8, 0.8, 0.8> }
  finish { ambient 0.1 diffuse 0.9 }
}

// a wall on the left, x = -8
plane { <1, 0, 0>, -8
  pigment { color rgb <0.6, 0.5, 0.3> }
  finish { ambient 0.1 diffuse 0.5 }
}
