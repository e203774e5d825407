camera { location <0,0,5> look_at <0,0,0> }
// a radius no double can hold
sphere { <0,0,0>, 1e999 pigment { color rgb <1,0,0> } }
