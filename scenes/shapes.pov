// Boxes, cones and cylinders along tilted axes, with no transforms: each shape's own parameters place it.
// The first box has its corners swapped; the blue cone has a zero base radius (a point, no disk).
camera {
  location  <0, 3, 12>
  up        <0, 1, 0>
  right     <1.33333, 0, 0>
  look_at   <0, 0.5, 0>
}

light_source {<-20, 30, 25> color rgb <1.5, 1.5, 1.5>}

plane {<0, 1, 0>, -1
  pigment {color rgb <0.7, 0.7, 0.7>}
  finish {ambient 0.3 diffuse 0.6}
}

box { <-2.5, 0.5, 1>, <-4.5, -1, -1>
  pigment {color rgb <0.9, 0.3, 0.2>}
  finish {ambient 0.2 diffuse 0.7}
}

cylinder { <-1.5, -1, 2>, <0.5, 2.5, -1>, 0.6
  pigment {color rgb <0.2, 0.8, 0.3>}
  finish {ambient 0.2 diffuse 0.7 specular 0.4 roughness 0.1}
}

cone { <2, 2.5, 0>, 0, <2, -1, 0>, 1.2
  pigment {color rgb <0.2, 0.4, 0.9>}
  finish {ambient 0.2 diffuse 0.7}
}

cone { <3.5, 1.5, 3>, 0.9, <5, 0.5, 1>, 0.3
  pigment {color rgb <0.9, 0.8, 0.2>}
  finish {ambient 0.2 diffuse 0.7}
}

cylinder { <-4, 2.5, -2>, <4, 2.5, -2>, 0.25
  pigment {color rgb <0.8, 0.2, 0.8>}
  finish {ambient 0.2 diffuse 0.7}
}
