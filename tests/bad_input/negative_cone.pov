camera { location <0,0,5> look_at <0,0,0> }
cone { <0,0,0>, -1, <0,1,0>, 0 }
