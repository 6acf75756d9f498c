// Shapes POV-Ray gives no uv coordinates (plane, cone, cylinder, prism, blob ...) show a
// uv-mapped pigment or normal at <x, y, 0> of the world point: the pattern does not vary
// along world z, and the object's transformations move the surface through it.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -5> look_at <0, 0, 0> angle 45 }
light_source { <-4, 8, -6> rgb 1 }
#declare Checker = pigment { uv_mapping checker rgb <1, 0.5, 0.1>, rgb <0.1, 0.3, 0.8> scale 0.2 }
plane { <0, 1, -0.3>, -0.8 pigment { rgb 1 } normal { uv_mapping bumps 1 scale 0.2 } }
cone { -y, 0.8, y, 0.3 pigment { Checker } normal { uv_mapping bumps 1 scale 0.2 }
  rotate 30 * y translate <1.2, 0, -1> }
cylinder { -y, y, 0.6 pigment { Checker } rotate <0, 40, 20> translate <-1.3, 0, 0> }
prism { -0.5, 0.5, 4, <-0.5, -0.5>, <0.5, -0.5>, <0, 0.6>, <-0.5, -0.5>
  pigment { Checker } rotate <-60, 0, 10> translate <0, 0.2, 0.5> }
