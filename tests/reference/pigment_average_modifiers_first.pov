// pigment_average_modifiers_first: turbulence and transformations written between `average`
// and its pigment_map apply to the average (left: turbulence, scale and rotate first; right:
// a warp first).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 3, -4> rgb 1 }
#declare Map = pigment_map {
  [1 checker rgb 1 rgb 0 scale 0.3]
  [1 gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] }]
}
plane { z, 0
  pigment { average turbulence 0.5 scale 2 rotate 20*z pigment_map { Map } }
  finish { ambient 0.3 }
  clipped_by { plane { x, 0 } }
}
plane { z, 0
  pigment { average warp { turbulence 0.4 } pigment_map { Map } }
  finish { ambient 0.3 }
  clipped_by { plane { -x, 0 } }
}
