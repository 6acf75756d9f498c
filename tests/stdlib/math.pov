// Calls every function and macro of math.inc with a few arguments and writes the results,
// one `name value..` line each, to probe.txt; tests/integration/includes.rs runs it with
// durer's embedded math.inc and with POV-Ray's and compares the two files.
#version 3.7;
#include "math.inc"
#fopen Out "probe.txt" write
#macro Put(Name, Value)
  #write (Out, Name, " ", vstr(5, <0, 0, 0, 0, 0> + (Value), " ", 0, 9), "\n")
#end

// Statistics (POV-Ray's Histogram reads the entry count from N).
#declare Values = array[9] {1, 5, 2.5, 3, 9, 4, 4.5, -2, 7.25}
#declare N = 9;
Put("Mean", Mean(Values))
Put("Std_Dev", Std_Dev(Values, Mean(Values)))
GetStats(Values)
#for (I, 0, 4) Put(concat("StatisticsArray ", str(I, 0, 0)), StatisticsArray[I]) #end
#for (Bins, 1, 4)
  Histogram(Values, Bins + 0.5)
  #for (I, 0, Bins - 1)
    Put(concat("HistogramArray ", str(Bins, 0, 0)), <HistogramArray[I][0], HistogramArray[I][1]>)
  #end
#end

// Float functions.
#for (A, -2.5, 2.5, 0.5)
  #declare S = str(A, 0, 1);
  Put(concat("trig ", S), <sind(A * 30), cosd(A * 30), tand(A * 20), atand(A), atan2d(A, 0.7)>)
  Put(concat("inverse trig ", S), <asind(A / 3), acosd(A / 3)>)
  Put(concat("max3 min3 ", S), <max3(A, 1, -A), min3(A, 1, -A)>)
  Put(concat("even odd ", S), <even(A), odd(A), even(A * 2), odd(A * 2)>)
  Put(concat("f_sqr sgn ", S), <f_sqr(A), sgn(A), sgn(A * 2 - 1)>)
  Put(concat("clip ", S), <clip(A, -1, 1.5), clip(A, 1, -1)>)
  Put(concat("clamp ", S), <clamp(A, -1, 1.5), clamp(A * 3, 0.5, 2)>)
  Put(concat("adj_range ", S), <adj_range(A, 2, 5), adj_range2(A, -1, 3, 10, 20)>)
  #for (Method, 0, 3)
    Put(concat("Interpolate ", S, " ", str(Method, 0, 0)), Interpolate(A, -3, 4, 2, 7, Method))
  #end
  Put(concat("Interpolate vector ", S), Interpolate(A, -3, 4, <1, 2, 3>, <-1, 0, 5>, 0.5))
#end

// Vectors.
#declare Vectors = array[6] {
  <1, 2, 3>, <-0.5, 0.25, 2>, <0, 0, 1>, <3, -3, 0>, <0.1, 0.1, 0.1>, <2, 0, -1>
}
#declare Colours = array[3] {
  <0.1, 0.2, 0.3, 0.4, 0.5>, <1, 0, 0.5, 0, 0.25>, <0.2, 0.2, 0.2, 0.2, 0.2>
}
#for (I, 0, 5)
  #declare A = Vectors[I];
  #declare B = Vectors[mod(I + 1, 6)];
  #declare S = str(I, 0, 0);
  Put(concat("VSqr ", S), VSqr(A))
  Put(concat("VPow ", S), VPow(A, 2) + VPow(A * A + 1, 0.5))
  Put(concat("VEq VZero ", S), <VEq(A, B), VEq(A, A), VZero(A), VZero(A * 0)>)
  Put(concat("VCos_Angle ", S), VCos_Angle(A, B))
  Put(concat("VAngle ", S), <VAngle(A, B), VAngleD(A, B), VAngle(A, A)>)
  Put(concat("VRotation ", S), <VRotation(A, B, vcross(A, B)), VRotation(A, B, -vcross(A, B))>)
  Put(concat("VRotationD ", S), <VRotationD(A, B, y), VRotationD(A, B, <0, 0, 0>)>)
  Put(concat("VDist ", S), VDist(A, B))
  Put(concat("VPerp_To_Vector ", S), VPerp_To_Vector(A))
  Put(concat("VPerp_To_Plane ", S), VPerp_To_Plane(A, B))
  Put(concat("VPerp_Adjust ", S), VPerp_Adjust(A, B))
  Put(concat("VProject_Plane ", S), VProject_Plane(A, B))
  Put(concat("VProject_Axis ", S), VProject_Axis(A, B))
  Put(concat("VMin VMax ", S), <VMin(A), VMax(A)>)
  Put(concat("VWith_Len ", S), VWith_Len(A, 2.5))
#end
Put("VPerp_To_Vector zero", VPerp_To_Vector(<0, 0, 0>))
Put("VPerp_To_Vector ties", VPerp_To_Vector(<1, 1, 1>) + VPerp_To_Vector(<1, 0, 0>))
#for (I, 0, 2)
  #declare A = Colours[I];
  #declare B = Colours[mod(I + 1, 3)];
  #declare S = str(I, 0, 0);
  Put(concat("VPow5D ", S), VPow5D(A, 3))
  Put(concat("VEq5D VZero5D ", S), <VEq5D(A, B), VEq5D(A, A), VZero5D(A), VZero5D(A * 0)>)
  Put(concat("VLength5D VDot5D ", S), <VLength5D(A), VDot5D(A, B)>)
  Put(concat("VNormalize5D ", S), VNormalize5D(A))
#end

// Derivatives.
#declare Field = function { x * x * y + sin(z) - x * z * 3 }
#declare Field_X = function { y * z }
#declare Field_Y = function { x * x - z }
#declare Field_Z = function { sin(x) * y }
// durer evaluates a function's identifiers when it is called, so the functions fn_Gradient,
// fn_Gradient_Directional and fn_Divergence return (which name the macro's parameters) are
// made here but not called.
#declare Gradient_Fn = fn_Gradient(Field)
#declare Slope_Fn = fn_Gradient_Directional(Field, <1, 2, -1>)
#declare Divergence_Fn = fn_Divergence(Field_X, Field_Y, Field_Z)
#for (I, 0, 5)
  #declare P = Vectors[I];
  #declare S = str(I, 0, 0);
  Put(concat("vGradient ", S), vGradient(Field, P))
  Put(concat("vCurl ", S), vCurl(Field_X, Field_Y, Field_Z, P))
  Put(concat("Divergence ", S), Divergence(Field_X, Field_Y, Field_Z, P))
  Put(concat("Gradient_Length ", S), Gradient_Length(Field, P))
  Put(concat("Gradient_Directional ", S), Gradient_Directional(Field, P, <0, 1, 1>))
#end
Put("__Gradient_Fn_Accuracy_", __Gradient_Fn_Accuracy_)
SetGradientAccuracy(-0.25)
Put("SetGradientAccuracy", __Gradient_Fn_Accuracy_)
Put("vGradient coarse", vGradient(Field, <1, 2, 3>))
#fclose Out
