// Tests: colour vectors longer than their keyword keep the extra components: `rgb <r, g, b, f>`
// is a filtering glass pane, `rgb <.., f, t>` and `rgbf <.., f, t>` transmit too, `rgbt <.., t, x>`
// takes the fourth as transmit (povray warns "Suspicious expression after rgb").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> }
light_source { <-4, 8, -6>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.3 } }
box { <-2.9, 0, -0.1>, <-1.6, 2, 0.1> pigment { rgb <1, 0.2, 0.2, 0.8> } }
box { <-1.3, 0, -0.1>, <0, 2, 0.1> pigment { rgb <0.2, 1, 0.2, 0.3, 0.5> } }
box { <0.3, 0, -0.1>, <1.6, 2, 0.1> pigment { rgbf <0.2, 0.2, 1, 0.2, 0.6> } }
box { <1.9, 0, -0.1>, <3.2, 2, 0.1> pigment { rgbt <1, 1, 0.2, 0.7, 0.9> } }
sphere { <0, 0.7, 2>, 0.7 pigment { rgb <0.9, 0.5, 0.1> } }
cylinder { <-2, 0, 2.5>, <-2, 2.5, 2.5>, 0.3 pigment { rgb <0.6, 0.6, 0.9> } }
