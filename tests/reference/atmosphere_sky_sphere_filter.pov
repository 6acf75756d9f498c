// atmosphere_sky_sphere_filter: sky_sphere layers with filter and with transmit stacked in a
// 3.7 scene: each layer passes filter · colour + transmit of what is below
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0.5, 0.3, 0.2> }
camera { location <0, 1, -5> look_at <0, 2.5, 2> angle 80 }
light_source { <-5, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sky_sphere {
  pigment { gradient y colour_map { [0 rgbf <0.9, 0.8, 0.6, 0.4>] [1 rgbf <0.1, 0.2, 0.6, 0.3>] } scale 2 translate -1 }
  pigment { bozo colour_map { [0 rgbt <0.8, 0.8, 0.8, 0.2>] [0.5 rgbt <0.9, 0.9, 0.9, 0.8>] [1 rgbt <1, 1, 1, 0.9>] } scale 0.3 }
  pigment { gradient x colour_map { [0 rgbf <1, 0.6, 0.6, 0.7>] [1 rgbf <0.6, 0.6, 1, 0.9>] } scale 2 translate -1 }
}
