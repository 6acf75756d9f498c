// Tests: boxes given by two corners (one with the corners in reverse order), a rotated box,
// a thin slab and a tall pillar, on a checker floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <1.5, 3.5, -6> look_at <0, 0.5, 0> angle 55 }
light_source { <5, 9, -4> rgb 1 }
background { rgb <0.15, 0.15, 0.2> }

plane { y, 0 pigment { checker rgb <0.7, 0.7, 0.7> rgb <0.3, 0.3, 0.35> } }
box { <-2.5, 0, -0.5>, <-1.5, 1, 0.5> pigment { rgb <0.9, 0.5, 0.1> } }
box { <0.6, 1.5, 0.6>, <-0.6, 0, -0.6> rotate y*35 pigment { rgb <0.2, 0.6, 0.9> } }
box { <1.4, 0, -1.5>, <2.8, 0.15, -0.3> pigment { rgb <0.8, 0.2, 0.5> } }
box { <1.6, 0, 1>, <2.2, 2.5, 1.6> pigment { rgb <0.85, 0.85, 0.8> } }
