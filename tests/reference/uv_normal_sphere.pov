// uv_mapping inside `normal { }` on spheres: the bumps follow the sphere's uv coordinates
// (crowding at the poles, unmoved by the object's rotation), and the uv-space slope tilts the
// world normal as it stands (POV-Ray's rule, measured).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -7> look_at <0, 0, 0> angle 45 }
light_source { <-4, 6, -6> rgb 1 }
sphere { 0, 1
  pigment { rgb <1, 0.7, 0.4> }
  normal { uv_mapping bumps 0.8 scale <0.04, 0.08, 1> }
  rotate <0, 30, 20> translate <-1.3, 0, 0>
}
sphere { 0, 1
  pigment { rgb <0.5, 0.8, 1> }
  normal { uv_mapping checker 1 scale <0.125, 0.25, 1> }
  finish { specular 0.4 }
  rotate <-20, 0, 0> translate <1.3, 0, 0>
}
plane { y, -1 pigment { rgb 0.6 } }
