// bounded_by_shadows: a kept bounded_by box (smaller than the object's own box) cuts what
// camera rays see but not the shadow; a bound larger in volume than the object's box is
// dropped even where it would cut; clipped_by { bounded_by } cuts the shadow too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.8, 0> angle 55 }
light_source { <-4, 8, -3> rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
sphere { <-2, 1, 0>, 0.9 bounded_by { box { <-3, 0, -0.2>, <-2, 2.1, 0.2> } }
  pigment { rgb <0.9, 0.3, 0.2> } }
sphere { <0, 1, 0.3>, 0.9 bounded_by { sphere { <0, 1, -0.7>, 0.7 } }
  pigment { rgb <0.2, 0.5, 0.9> } }
sphere { <2, 1, 0>, 0.9 bounded_by { box { <0.8, 0, -1.2>, <3.2, 1.3, 1.2> } }
  pigment { rgb <0.3, 0.8, 0.3> } }
sphere { <0.6, 0.7, -2>, 0.6 bounded_by { box { <0, 0, -3>, <1.2, 0.9, -1> } } clipped_by { bounded_by }
  pigment { rgb <0.9, 0.8, 0.2> } }
