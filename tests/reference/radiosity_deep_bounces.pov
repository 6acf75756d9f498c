// radiosity_deep_bounces: a closed room with coloured walls lit by one point light, with
// three bounces of indirect light; POV-Ray gathers `count` rays per sample at the first
// bounce and half as many at each deeper one (80, 40, 20 here)
#version 3.7;
global_settings {
  radiosity {
    pretrace_start 0.08 pretrace_end 0.04
    count 80 recursion_limit 3 nearest_count 5 error_bound 1
  }
}
camera { location <0, 1, -3.5> look_at <0, 1, 0> angle 70 }
light_source { <0.5, 1.8, -0.5> rgb 1 }
#declare Matte = finish { diffuse 0.75 ambient 0 }
box { <-2, 0, -4>, <2, 2, 2> inverse pigment { rgb 0.9 } finish { Matte } }
box { <-2.01, -0.1, -4>, <-1.99, 2.1, 2> pigment { rgb <0.57, 0.025, 0.025> } finish { Matte } }
box { <1.99, -0.1, -4>, <2.01, 2.1, 2> pigment { rgb <0.025, 0.236, 0.025> } finish { Matte } }
box { <-0.8, 0, 0>, <-0.2, 1.2, 0.6> rotate y * 20 pigment { rgb 0.9 } finish { Matte } }
sphere { <0.7, 0.4, -0.3>, 0.4 pigment { rgb 0.9 } finish { Matte } }
