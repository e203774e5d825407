// The three sphere_sweep splines through the same spheres, to compare with POV-Ray's picture:
//   raytrace render sphere_sweep.pov 320 240   /   povray +Isphere_sweep.pov +W320 +H240 -A
#version 3.7;
camera { location <0, 2, -9> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 10, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
plane { y, -1.6 pigment { checker rgb 1 rgb 0.5 } }

#declare Spheres = array[6] { <-2.5, -0.5, 0>, <-2, 0, 0>, <-0.5, 1, 0>, <0.5, -0.5, 0.5>, <2, 0.5, 0>, <2.5, 1, 0.5> }
#declare Radii = array[6] { 0.2, 0.3, 0.6, 0.2, 0.5, 0.3 }

sphere_sweep { linear_spline 4, Spheres[1], Radii[1], Spheres[2], Radii[2], Spheres[3], Radii[3], Spheres[4], Radii[4]
  tolerance 1e-4 pigment { rgb <1, 0.6, 0.3> } finish { phong 0.5 } translate <0, 1.8, 1> }
sphere_sweep { b_spline 6, Spheres[0], Radii[0], Spheres[1], Radii[1], Spheres[2], Radii[2], Spheres[3], Radii[3],
  Spheres[4], Radii[4], Spheres[5], Radii[5] pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.5 } }
sphere_sweep { cubic_spline 6, Spheres[0], Radii[0], Spheres[1], Radii[1], Spheres[2], Radii[2], Spheres[3], Radii[3],
  Spheres[4], Radii[4], Spheres[5], Radii[5] pigment { rgb <0.4, 0.5, 1> } finish { phong 0.5 } translate <0, -1.2, -1.5> }
