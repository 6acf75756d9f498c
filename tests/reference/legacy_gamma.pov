// Tests: a scene without #version and without assumed_gamma: POV-Ray 3.7 warns and turns
// gamma correction off for compatibility, so colours are written as computed (mid-tones
// come out darker than the same scene under assumed_gamma 1.0).

camera { location <0, 2.5, -6> look_at <0, 0.7, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
background { color rgb <0.2, 0.3, 0.5> }

plane { y, 0 pigment { checker color rgb 0.5 color rgb 0.25 } }
sphere { <-1.5, 0.8, 0>, 0.8 pigment { color rgb <0.5, 0.2, 0.1> } }
sphere { <0.5, 0.6, -0.5>, 0.6 pigment { color rgb <0.1, 0.4, 0.2> } finish { phong 0.5 } }
box { <1.2, 0, 0.2>, <2.4, 1.2, 1.4> pigment { color rgb 0.5 } }
