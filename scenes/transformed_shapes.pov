// The same kinds of shapes placed by transforms, in file order: a sheared-looking (non-uniformly scaled, then
// turned) box, a squashed cylinder, a cone turned on its side, and an ellipsoid. Each transform list is read
// left to right; `rotate <a, b, c>` turns about z, then y, then x (the course's order).
camera {
  location  <0, 4, 14>
  up        <0, 1, 0>
  right     <1.33333, 0, 0>
  look_at   <0, 0.5, 0>
}

light_source {<20, 30, 25> color rgb <1.5, 1.5, 1.5>}

plane {<0, 1, 0>, 0
  pigment {color rgb <0.6, 0.6, 0.7>}
  finish {ambient 0.3 diffuse 0.6}
  rotate <0, 0, 5>
  translate <0, -1.5, 0>
}

box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5>
  scale <4, 1, 1>
  rotate <30, 0, 20>
  translate <-3, 1, -2>
  pigment {color rgb <0.9, 0.3, 0.2>}
  finish {ambient 0.2 diffuse 0.7}
}

cylinder { <0, 0, 0>, <0, 1, 0>, 1
  pigment {color rgb <0.2, 0.8, 0.3>}
  finish {ambient 0.2 diffuse 0.7}
  scale <1.5, 2, 0.5>
  rotate <0, 45, 0>
  translate <2.5, -1, 1>
}

cone { <0, 0, 0>, 1, <0, 2.5, 0>, 0.2
  pigment {color rgb <0.2, 0.4, 0.9>}
  finish {ambient 0.2 diffuse 0.7}
  rotate <0, 0, -90>
  translate <-1, -0.5, 2.5>
}

sphere { <0, 0, 0>, 1
  pigment {color rgb <0.9, 0.8, 0.2>}
  finish {ambient 0.2 diffuse 0.7}
  scale <2, 0.75, 1>
  rotate <0, -30, 0>
  translate <3, 2.5, -3>
}
