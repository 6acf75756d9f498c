// media_emission_beam: method 3 media that only emit and absorb are still split at the edges
// of a spotlight's beam, as POV-Ray 3.7 does (measured: sampling the whole stretch at once
// puts the centre column off by up to 6/255)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <0, 4, 0> rgb 3 spotlight point_at <0, 0, 0> radius 8 falloff 12 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
box { <-2, 0.01, -1>, <2, 2, 1>
  pigment { rgbt 1 } hollow
  interior { media { method 3 intervals 1 samples 3, 3
    emission rgb <0.3, 0.2, 0.1>
    absorption 0.4
    density { spherical scale 2 color_map { [0 rgb 0] [1 rgb 1] } }
  } }
}
