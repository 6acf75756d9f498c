// Shadow rays through media sample it as POV-Ray does: the pieces of method 3 at the
// container's `samples`, the first taken at the far end for rays that enter the container
// from outside. Top: a step-density absorber (samples 1) shades a thin scattering slab;
// bottom: a scattering slab with a ramp density (samples 4) shades itself.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0.5, 0, -5> look_at <0.5, 0, 0> right x * 3.2 up y * 2.4 }
light_source { <100, 0, 0> rgb 1 parallel point_at 0 }
box { <0.4, 0.06, -0.5>, <0.6, 1, 0.5> hollow pigment { rgbf 1 }
  interior { media { scattering { 1, 0.5 extinction 0 } } } }
box { <1, 0.06, -1>, <1.999, 1, 1> hollow pigment { rgbf 1 }
  interior { media { absorption 2 samples 1
    density { gradient x color_map { [0 rgb 1] [0.4 rgb 1] [0.4 rgb 0] [1 rgb 0] } } } } }
box { <-1, -1, -0.05>, <0.999, -0.06, 0.05> hollow pigment { rgbf 1 }
  interior { media { scattering { 1, 2 extinction 1 } samples 4
    density { gradient x color_map { [0 rgb 0.2] [1 rgb 1] } } } } }
