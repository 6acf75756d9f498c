// uv_mapping on spheres, boxes and tori, which POV-Ray gives uv coordinates. Rotated and
// scaled objects keep their uv layout.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -9> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 8, -6> rgb 1 }
#declare UV = texture {
  uv_mapping
  pigment { checker rgb <1, 0.4, 0.1>, rgb <0.1, 0.3, 0.9> scale <0.125, 0.25, 1> }
  finish { ambient 0.3 }
}
#declare Ramp = pigment {
  uv_mapping gradient x color_map { [0 rgb 0] [1 rgb <1, 1, 0.3>] }
}
sphere { 0, 1 texture { UV } rotate <0, 40, 20> translate <-2.4, 0.2, 0> }
box { -1, 1 texture { UV } rotate <20, 30, 0> scale 0.8 translate <0, 0.2, 0> }
torus { 0.8, 0.35 texture { UV } rotate <-50, 20, 0> translate <2.4, 0.3, 0> }
sphere { 0, 0.6 pigment { Ramp } translate <-1.2, -0.5, -2> }
torus { 0.5, 0.2 pigment { Ramp } rotate x * -60 translate <1.2, -0.4, -2> }

plane { y, -1.2 pigment { rgb 0.5 } }
