// transmit_negative: transmit below 0 and above 1 is not clamped: (1 - t)·P + t·B, so a
// negative amount subtracts the background and one above 1 brightens it; with filter, and
// through a refracting sphere
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0.2, 0.3, 0.4> }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.8, 0.2> rgb <0.2, 0.5, 0.9> } }
#declare Panel = box { <-0.6, 0, -0.05>, <0.6, 1.6, 0.05> }
object { Panel pigment { rgb <0.8, 0.2, 0.1> transmit -1 } translate <-2.4, 0, 0> }
object { Panel pigment { rgb <0.8, 0.2, 0.1> transmit -0.5 } translate <-1.0, 0, 0> }
object { Panel pigment { rgb <0.1, 0.3, 0.2> transmit 2 } translate <0.4, 0, 0> }
object { Panel pigment { rgbft <0.5, 0.9, 0.5, 0.6, -0.4> } translate <1.8, 0, 0> }
sphere { <0.5, 0.6, -1.6>, 0.5
  pigment { rgb <0.9, 0.9, 0.2> transmit -0.3 }
  interior { ior 1.3 }
}
