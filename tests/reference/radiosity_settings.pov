// radiosity_settings: a wide emissive ceiling panel as the only light over a box and a sphere, with
// count and its direction pool, error_bound, brightness, gray_threshold, nearest_count,
// minimum/maximum_reuse and the pretrace sizes set; two bounces
// tolerance: 0.04
// (POV-Ray draws its 60 rays per sample from its own direction table, so the noise of each
// cached sample differs: about 2.1% of pixels differ by more than 24/255, blocks by 5.5/255)
#version 3.7;
global_settings {
  radiosity {
    count 60, 120 error_bound 1.2 brightness 1.3 gray_threshold 0.4 nearest_count 6
    minimum_reuse 0.01 maximum_reuse 0.15 pretrace_start 0.1 pretrace_end 0.05
    recursion_limit 2 low_error_factor 0.6 always_sample off
  }
}
camera { location <0, 2.5, -4> look_at <0, 0.5, 0> angle 60 }
background { rgb 0 }
box { <-4, 3, -3>, <4, 3.1, 4> pigment { rgb 1 } finish { diffuse 0 emission 1.5 } }
plane { y, 0 pigment { rgb <0.6, 0.7, 0.9> } }
box { <-1.2, 0, -0.4>, <-0.4, 0.8, 0.4> rotate y * 20 pigment { rgb <0.9, 0.2, 0.1> } }
sphere { <0.7, 0.5, 0>, 0.5 pigment { rgb <0.9, 0.9, 0.3> } }
