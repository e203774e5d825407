camera { location <0,0,5> look_at <0,0,0> }
light_source { <5,5,5> }
