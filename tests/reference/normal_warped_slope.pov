// normal_warped_slope: slope-derived normals of warped patterns — the warps and turbulence
// move the centre point only, the pattern is sampled around it unwarped (granite with
// turbulence, gradient x with turbulence bumping only along its wrap, a black hole)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.3, 0> angle 55 }
light_source { <-6, 9, -5> rgb 1 }
plane { y, 0 pigment { rgb 0.9 } normal { gradient x 1 turbulence 1 scale 2 } }
sphere { <-1.7, 1, 0>, 1 pigment { rgb 1 } normal { granite 0.7 turbulence 0.2 scale 1.2 } }
sphere { <0.6, 0.9, 0.6>, 0.9 pigment { rgb <0.7, 0.8, 1> } normal { bozo 1 turbulence 0.6 scale 0.3 accuracy 0.005 } }
box { <-0.7, 0, -0.7>, <0.7, 1.2, 0.7> rotate y*30 translate <2.1, 0, -1>
  pigment { rgb <1, 0.9, 0.7> } normal { granite 0.6 warp { black_hole <0, 0.6, 0>, 1 strength 2 } scale 2 } }
