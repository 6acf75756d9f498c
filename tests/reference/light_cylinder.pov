// Tests: cylinder lights: beams of constant width around their axis, with radius,
// falloff and tightness; light runs along the axis, so the sphere's shadow in the grazing
// beam does not spread.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0, 0> angle 50 }
light_source { <-2, 6, 0> rgb 1 cylinder point_at <-2, 0, 0> radius 0.6 falloff 1.2 }
light_source { <6, 2, 0> rgb <0.5, 0.7, 1> cylinder point_at <0, 0.5, 0> radius 0.8 falloff 1 tightness 1 }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <1, 0.5, 0>, 0.5 pigment { rgb <0.9, 0.6, 0.3> } }
