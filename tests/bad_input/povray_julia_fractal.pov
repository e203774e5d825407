#version 3.7;
camera { location <0, 1, -4> look_at 0 }
  julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15 pigment { rgb 1 } }
