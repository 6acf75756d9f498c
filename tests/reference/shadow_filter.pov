// Tests: shadows through transparent objects: a red filtering pane (rgbf) casts a red
// shadow, a grey transmitting pane (rgbt) a lighter colourless one, an rgbft sphere a
// tinted one, next to an opaque cylinder's black shadow.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -6> look_at <0, 0.5, 0.5> angle 55 }
light_source { <-2, 7, -3> rgb 1 }
background { rgb <0.1, 0.1, 0.15> }

plane { y, 0 pigment { rgb <0.95, 0.95, 0.95> } }
box { <-2.6, 0, 0>, <-1.2, 1.5, 0.05> pigment { rgbf <1, 0.2, 0.2, 0.9> } }
box { <-0.7, 0, 0>, <0.7, 1.5, 0.05> pigment { rgbt <0.5, 0.5, 0.5, 0.6> } }
sphere { <1.9, 0.8, 0.2>, 0.7 pigment { rgbft <0.2, 0.4, 1, 0.6, 0.2> } }
cylinder { <0.8, 0, -1.6>, <0.8, 1, -1.6>, 0.25 pigment { rgb <0.9, 0.8, 0.2> } }
