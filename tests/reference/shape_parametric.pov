// shape_parametric: a ring given by its uv parametrisation, tilted (POV-Ray's parametric
// search is slow: the scene keeps the surface small and the accuracy coarse).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0, 0> angle 60 }
light_source { <-5, 8, -6> rgb 1 }
plane { y, -1.2 pigment { rgb <0.8, 0.8, 0.7> } }
parametric {
  function { (0.7 + 0.2*cos(v))*cos(u) }
  function { 0.2*sin(v) }
  function { (0.7 + 0.2*cos(v))*sin(u) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { box { <-1, -0.3, -1>, <1, 0.3, 1> } }
  max_gradient 1
  accuracy 0.01
  rotate <-50, 0, 0>
  pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.5 }
}
