// light_group: a group light lights only its group (and its objects still shadow the rest);
// a second group with global_lights on is lit by the scene light too; groups move their
// lights with their transformations; an outside sphere shadows a group object from the
// group's light
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 55 }
background { rgb 0.1 }
light_source { <-6, 8, -5> rgb <0.5, 0.5, 0.6> }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-2.2, 1, 0>, 0.7 pigment { rgb <0.9, 0.9, 0.3> } }
sphere { <1.2, 2.3, -1.6>, 0.3 pigment { rgb <0.3, 0.9, 0.4> } }
light_group {
  light_source { <3, 3, -3> rgb <1, 0.3, 0.2> }
  sphere { <0, 1, 0>, 0.9 pigment { rgb 1 } }
  plane { y, 0.01 pigment { rgb 0.5 } clipped_by { box { <-1.5, -1, -1>, <1.5, 1, 2> } } }
  rotate 10*y
}
light_group {
  light_source { <1, 4, -4> rgb <0.2, 0.4, 1> }
  box { <1.4, 0, -0.6>, <2.8, 1.4, 0.8> pigment { rgb 1 } }
  global_lights on
}
