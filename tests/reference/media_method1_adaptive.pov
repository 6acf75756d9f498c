// Media method 1: random samples per interval, more taken until the confidence test
// with `variance` passes (samples 4 to 40). POV-Ray's samples are random, so the density
// is smooth and the comparison measures the average.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 0.6, 0> angle 45 }
light_source { <4, 6, -3> rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { <0, 1, 0>, 1.2 hollow pigment { rgbf 1 }
  interior { media {
    method 1 intervals 2 samples 4, 40 confidence 0.95 variance 1/256
    emission <0.3, 0.15, 0.05> absorption 0.4 scattering { 1, 0.3 }
    density { spherical color_map { [0 rgb 0] [1 rgb 1] } scale 1.2 translate <0, 1, 0> }
  } } }
