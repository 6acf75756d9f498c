// An interior given after `translate` keeps its density where it was written (POV-Ray
// moves only densities written before the transformation): the left sphere's stripes
// stay in place, the right one's move with it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at 0 angle 50 }
#declare Stripes = interior { media { emission 1.2
  density { gradient x color_map { [0 rgb 0] [0.5 rgb 0] [0.5 rgb 1] [1 rgb 1] } scale 0.8 } } }
sphere { 0, 1 hollow pigment { rgbf 1 } translate <-1.25, 0, 0> interior { Stripes } }
sphere { 0, 1 hollow pigment { rgbf 1 } interior { Stripes } translate <1.25, 0, 0> }
