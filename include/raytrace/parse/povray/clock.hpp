// The values of POV-Ray's animation built-ins for one frame, as the command line sets them (+KFI, +KFF, +KI,
// +KF, +KC, +K): all 0 for a still picture, as in POV-Ray.
#pragma once

namespace rt::povray {

struct Clock {
  double clock = 0, delta = 0;              // clock, clock_delta
  double initialClock = 0, finalClock = 0;  // initial_clock, final_clock
  int frame = 0, initialFrame = 0, finalFrame = 0;  // frame_number, initial_frame, final_frame
  bool on = false;                                  // clock_on: the frame is one of an animation
};

}  // namespace rt::povray
