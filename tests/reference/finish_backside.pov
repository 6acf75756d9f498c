// Tests: backside diffuse (`diffuse 0.6, 0.4`) on a thin translucent panel lit from
// behind, and double_illuminate on an open cylinder lit from outside.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 55 }
light_source { <1, 4, 6> rgb 1 }
light_source { <-3, 5, -5> rgb 0.3 }
plane { y, 0 pigment { rgb 0.8 } }
box { <-2.5, 0, -0.01>, <-0.3, 2, 0.01> pigment { rgb <0.9, 0.8, 0.4> }
  finish { diffuse 0.6, 0.4 } no_shadow }
cylinder { <1.4, 0, 0>, <1.4, 1.6, 0>, 0.8 open pigment { rgb <0.4, 0.7, 0.9> } double_illuminate }
