// bounded_by: POV-Ray 3.7 gives the object the bounding object's box, and rays that miss
// that box miss the object (the bounding object's exact shape does not matter). Shadows of
// objects cut this way differ from POV-Ray's (not understood yet), so this light is shadowless.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.3, 0.5, -4> look_at 0 angle 40 }
light_source { <3, 5, -4> rgb 1 shadowless }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } bounded_by { box { <-0.5, -0.6, -0.5>, <0.6, 0.5, 0.5> } } }
sphere { <1.2, 0, 1>, 0.5 pigment { rgb <0.2, 0.5, 1> } bounded_by { sphere { <1.2, 0.6, 1>, 0.4 } } }
difference {
  box { <-1.6, -0.3, -0.3>, <-1, 0.3, 0.3> }
  sphere { <-1.3, 0.3, -0.3>, 0.2 }
  bounded_by { box { <-1.5, -1, -1>, <-1.1, 0.2, 1> } }
  pigment { rgb <0.4, 0.9, 0.3> }
}
plane { y, -1 pigment { rgb 0.7 } }
