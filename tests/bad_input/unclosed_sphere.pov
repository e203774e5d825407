// invalid/unclosed_sphere.pov: a scene with a mistake, for the error-path tests. The sphere's closing brace
// is missing, so the file ends inside it.
camera { location <0, 0, 10> look_at <0, 0, 0> }

sphere { <0, 0, 0>, 2
  pigment { color rgb <1, 0, 0> }
