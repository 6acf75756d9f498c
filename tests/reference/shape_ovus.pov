// shape_ovus: eggs of several radius ratios (the pointed end down or up, the top sphere
// swallowing the bottom one when it is more than twice as big), one scaled and tilted.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, -1 pigment { rgb <0.8, 0.8, 0.7> } }
ovus { 1, 0.6 translate <-2.6, 0, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
ovus { 0.5, 0.9 translate <-0.6, -0.5, 0> pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.5 } }
ovus { 0.4, 1.0 translate <1.4, -0.6, 0.5> pigment { rgb <0.3, 0.8, 0.3> } }
ovus { 0.7, 0.15 scale <1, 1.5, 1> rotate <0, 0, -30> translate <3, 0.2, 1>
  pigment { rgb <0.9, 0.8, 0.2> } finish { phong 0.5 } }
ovus { 0.3, 0.3 translate <0.5, 1.9, -1> pigment { rgb <0.8, 0.3, 0.8> } }
