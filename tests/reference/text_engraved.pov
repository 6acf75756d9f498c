// Text cut out of a box: the letters of an inverted (subtracted) text are intersected, so the
// box keeps its faces everywhere outside the letters.
// needs: timrom.ttf
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1.2, 1.5, -4> look_at <1.2, 0.3, 0> angle 50 }
light_source { <-3, 6, -6> rgb 1 }
difference {
  box { <-0.3, -0.3, 0>, <2.8, 1, 1> }
  text { ttf "timrom.ttf" "ABC" 0.5, 0 translate <0, 0, -0.1> }
  pigment { rgb <0.9, 0.7, 0.4> }
}
plane { y, -0.3 pigment { checker rgb 1 rgb 0.6 } }
