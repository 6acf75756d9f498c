// radiosity_deep_reuse: a white room lit by a spotlight lying in its ceiling's plane and
// aimed at the floor, so most of the room sees only second and third bounces. Pins how
// deeper bounces reuse their samples: the reuse radius clamps the harmonic mean distance
// (before `error_bound` scales it) between `minimum_reuse` and `maximum_reuse` times the
// length of the light's path to the eye, and the pretrace's `low_error_factor` lowers only
// the first bounce's radii; also that a light in a surface's plane is not shadowed by it
#version 3.7;
global_settings {
  radiosity {
    pretrace_start 0.08 pretrace_end 0.02
    count 60 recursion_limit 3 nearest_count 5 error_bound 0.6
  }
}
camera { location <0, 1, -3.9> look_at <0, 0.9, 0> angle 60 }
light_source {
  <0, 2, 0> rgb 3
  spotlight radius 20 falloff 30 point_at <0.3, 0, 0.5>
}
#declare Matte = finish { diffuse 0.9 ambient 0 }
box { <-2, 0, -4>, <2, 2, 2> inverse pigment { rgb 0.9 } finish { Matte } }
box { <-2.01, -0.1, -4>, <-1.99, 2.1, 2> pigment { rgb <0.7, 0.1, 0.1> } finish { Matte } }
box { <-0.9, 0, 0.6>, <-0.3, 1.4, 1.2> rotate y * 25 pigment { rgb 0.9 } finish { Matte } }
