// Stability scene S1 (stability.md §3): unit spheres on a floor between two facing mirrors, lit by a light
// 5° above the horizon, so shadow rays graze the floor and reflections recurse. The chart's base scene;
// s4_far_*.pov are this scene moved away from the origin.
camera {
  location <0, 3, 12>
  up <0, 1, 0>
  right <1.33333, 0, 0>
  look_at <0, 1, 0>
}

// elevation atan(3.5 / 40) = 5.0° seen from the spheres
light_source { <40, 3.5, -2> color rgb <1.5, 1.5, 1.5> }
light_source { <-4, 10, 10> color rgb <0.3, 0.3, 0.3> }

sphere { <-2.2, 1, 0>, 1
  pigment { color rgb <0.9, 0.3, 0.2> }
  finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 0.05 }
}
sphere { <0, 1, -1.5>, 1
  pigment { color rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.05 diffuse 0.2 specular 0.8 roughness 0.02 reflection 0.8 }
}
sphere { <2.2, 1, 0>, 1
  pigment { color rgb <0.2, 0.4, 0.9> }
  finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 0.05 }
}

plane { <0, 1, 0>, 0
  pigment { color rgb <0.7, 0.7, 0.6> }
  finish { ambient 0.15 diffuse 0.8 }
}

// the two mirrors, facing each other across the scene
plane { <1, 0, 0>, -6
  pigment { color rgb <0.95, 0.95, 0.95> }
  finish { ambient 0.02 diffuse 0.05 reflection 0.85 }
}
plane { <-1, 0, 0>, -6
  pigment { color rgb <0.95, 0.95, 0.95> }
  finish { ambient 0.02 diffuse 0.05 reflection 0.85 }
}
