// Functions of the standard include files that take pigments, patterns, transforms and
// functions (values printed by POV-Ray 3.7 at these points).
#version 3.7;
#include "functions.inc"
#include "math.inc"
#include "transforms.inc"
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#declare P = pigment { checker color rgb 1 color rgb 0 }
#declare F = function { pigment { P } }
Check(vlength(F(0.5, 0.5, 0.5) - <1, 1, 1>) < 1e-9, "a pigment function")
Check(abs(f_agate(0.3, 0.2, 0.1) - 0.370484) < 1e-6, "f_agate")
Check(vlength(eval_pigment(P, <0.5, 0.5, 0.5>) - <1, 1, 1>) < 1e-9, "eval_pigment")
#declare T = transform { rotate 90*y translate x }
#declare V = vtransform(<1, 0, 0>, T);
Check(vlength(V - <1, 0, -1>) < 1e-9, "vtransform")
Check(vlength(vinv_transform(V, T) - <1, 0, 0>) < 1e-9, "vinv_transform")
#declare Fn = function { x*x + y*y + z*z }
#declare Gr = fn_Gradient(Fn);
Check(abs(Gr(1, 2, 3) - 7.4833) < 1e-4, "fn_Gradient")
