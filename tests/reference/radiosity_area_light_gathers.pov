// radiosity_area_light_gathers: radiosity's gathering rays light their hits from an area light's centre alone (one shadow ray), as POV-Ray does: a disc under the centre of a big area light shadows the whole floor for the gathers but only a spot for the camera, so the ceiling, lit only by bounced light, stays dim
#version 3.7;
global_settings { assumed_gamma 1.0 radiosity { count 100 recursion_limit 1 nearest_count 5 error_bound 0.5 } }
camera { location <0, 1.2, -3.6> look_at <0, 1.3, 0> angle 75 }
light_source { <0, 2.3, 0> rgb 1.2 area_light x * 3, z * 3, 8, 8 }
disc { <0, 2.2, 0>, y, 0.25 pigment { rgb 0.1 } }
box { <-2, 0, -4>, <2, 2.5, 2> inverse pigment { rgb 0.9 } }
box { <-2.01, -0.1, -4>, <-1.99, 2.6, 2> pigment { rgb <0.9, 0.2, 0.2> } }
sphere { <0.6, 0.4, 0.3>, 0.4 pigment { rgb <0.3, 0.4, 0.9> } }
