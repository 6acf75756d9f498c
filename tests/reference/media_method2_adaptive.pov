// Media method 2: evenly spaced samples moved by `jitter`, with extra samples while the
// confidence test fails (samples 3 to 20, confidence 0.8, variance 1/64, intervals 3).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 0.6, 0> angle 45 }
light_source { <-4, 6, -3> rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
box { <-1.5, 0, -1>, <1.5, 2, 1> hollow pigment { rgbf 1 }
  interior { media {
    method 2 intervals 3 samples 3, 20 confidence 0.8 variance 1/64 jitter 0.5
    emission <0.05, 0.2, 0.3> absorption 0.3 scattering { 2, 0.4 extinction 0.5 }
    density { gradient y color_map { [0 rgb 1] [1 rgb 0.1] } scale 2 }
  } } }
