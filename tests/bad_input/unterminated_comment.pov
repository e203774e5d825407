camera { location <0,0,5> look_at <0,0,0> }
/* a comment that never ends
sphere { <0,0,0>, 1 }
