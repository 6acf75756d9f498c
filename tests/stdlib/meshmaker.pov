// meshmaker.inc's macros making meshes from splines and functions: Lathe, TwoVarSurf,
// MSM (from an array of splines), Parametric, Prism (from BuildSpline's spline).
// meshmaker.png is POV-Ray 3.7's render with its own meshmaker.inc, made like the reference
// images (povray -D +Imeshmaker.pov +Omeshmaker.png +W160 +H120 +WT1 -GA); the includes test
// renders this scene with durer and compares.
#version 3.7;
#include "meshmaker.inc"
global_settings { assumed_gamma 1 }
camera { location <0, 6, -14> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 8, -6>, rgb 1 }
light_source { <6, 3, -3>, rgb 0.5 }
background { rgb <0.2, 0.3, 0.5> }
#declare Tan = pigment { rgb <1, 0.6, 0.3> }
#declare Profile = spline { cubic_spline -0.25, <0.2, -0.2, 0> 0, <0.5, 0, 0> 0.5, <1, 1, 0> 1, <0.3, 2, 0> 1.25, <0.2, 2.5, 0> }
object { Lathe(Profile, 20, 360, 24, "") pigment { Tan } translate <-4, 0, 0> }
#declare Wave = function(u, v) { sin(u * 3) * 0.3 + v * v * 0.1 }
object { TwoVarSurf(Wave, <-1, 1>, <-1, 1>, 12, 10, "") pigment { Tan } translate <0, 0, 0> }
#declare Arr = array[4] { <0, 0, 0>, <1, 0.5, 0>, <2, 0, 0>, <3, 0.5, 0> }
#declare Spl = BuildSpline(Arr, "C")
#declare Shapes = array[4] {
  spline { linear_spline 0, <-1, 0, 0> 1, <0, 0, 1> 2, <1, 0, 0> 3, <0, 0, -1> 4, <-1, 0, 0> },
  spline { linear_spline 0, <-1, 1, 0> 1, <0, 1, 1.5> 2, <1, 1, 0> 3, <0, 1, -1> 4, <-1, 1, 0> },
  spline { linear_spline 0, <-0.5, 2, 0> 1, <0, 2, 0.5> 2, <0.5, 2, 0> 3, <0, 2, -0.5> 4, <-0.5, 2, 0> },
  spline { linear_spline 0, <-1, 3, 0> 1, <0, 3, 1> 2, <1, 3, 0> 3, <0, 3, -1> 4, <-1, 3, 0> }
}
object { MSM(Shapes, 16, "c", 12, "") pigment { Tan } translate <4, -1, 0> }
object { Parametric(function(u, v) { cos(u) * (1 + 0.3 * cos(v)) }, function(u, v) { 0.3 * sin(v) }, function(u, v) { sin(u) * (1 + 0.3 * cos(v)) }, <0, 0>, <2 * pi, 2 * pi>, 16, 10, "") pigment { Tan } translate <0, 2.5, 2> }
object { Prism(Spl, 12, 1, 3, "") pigment { Tan } translate <-2, -2, -3> }
