// A `shadowless` light lights no scattering media (measured in POV-Ray 3.7: the box of
// media and the atmosphere stay dark under it), though it lights the wall behind them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> direction z right x * 4 up y * 3 }
background { rgb 0 }
light_source { <-3, 30, -10>, 0.8 shadowless }
light_source { <30, 30, -10>, 0.3 }
media { scattering { 1, 0.005 } }
box { <-1.5, -1, 0>, <1.5, 1, 1> hollow pigment { rgbf 1 } interior { media { scattering { 1, 0.4 } } } }
plane { -z, -20 pigment { checker rgb 1 rgb 0.5 scale 1 } }
