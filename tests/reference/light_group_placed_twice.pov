// light_group_placed_twice: one declared light_group placed twice; each placement is a
// group of its own, so each sphere is lit by its own group's light only
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -9> look_at <0, 0.5, 0> angle 50 }
background { rgb 0.1 }
#declare Group = light_group {
  light_source { <-1.5, 1, -1.5> rgb 1 }
  sphere { <0, 0.8, 0>, 0.8 pigment { rgb 1 } }
  plane { y, 0 pigment { rgb <0.3, 0.5, 0.3> } clipped_by { box { <-1.4, -1, -1.4>, <1.4, 1, 1.4> } } }
}
object { Group translate -1.5*x }
object { Group translate 1.5*x rotate 10*y }
