// Splines: every kind, inside and outside the range; expected values printed by POV-Ray 3.7.
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#macro Near(V, W) (vlength(V - W) < 1e-8) #end
#declare Points = spline {
  0, <0,0,0>
  1, <1,2,0>
  2.5, <3,1,1>
  3, <4,4,2>
  4.5, <2,5,0>
}
Check(Near(Points(-1), <0,0,0>), "linear before the first point")
Check(Near(Points(1.2), <1.266666667,1.866666667,0.133333333>), "linear")
Check(Near(Points(9), <2,5,0>), "linear after the last point")
Check(Near(Points(0.2, quadratic_spline), <0.178666667,0.570666667,-0.042666667>), "quadratic, first segment")
Check(Near(Points(2.6, quadratic_spline), <3.186666667,1.466666667,1.173333333>), "quadratic")
Check(Near(Points(4.2, quadratic_spline), <3,5.76,1>), "quadratic, last segment")
Check(Near(Points(0.5, cubic_spline), <1,2,0>), "cubic before the second point")
Check(Near(Points(1.2, cubic_spline), <1.233925926,1.989925926,0.067851852>), "cubic")
Check(Near(Points(2.8, cubic_spline), <3.704,2.832,1.688>), "cubic")
Check(Near(Points(4, cubic_spline), <4,4,2>), "cubic after the next-to-last point")
Check(Near(Points(0.2, natural_spline), <0.203440860,0.636731183,0>), "natural")
Check(Near(Points(3.8, natural_spline), <3.646725607,5.867877340,1.663407407>), "natural")
// A copy keeps the original's points and takes more; a kind given later replaces the kind.
#declare Longer = spline { Points 5.5, <0,0,0> }
Check(Near(Longer(5), <1,2.5,0>), "a copied spline with a point added")
Check(Near(Points(5), <2,5,0>), "the original is unchanged")
#declare Smooth = spline { Points cubic_spline }
Check(Near(Smooth(1.2), <1.233925926,1.989925926,0.067851852>), "a copy with another kind")
// Floats count as two equal components; the widest point sets the size.
#declare Flat = spline { 0, 1 1, 3 }
#declare Value = Flat(0.5);
Check((Value.x = 2 & Value.y = 2), "float points")
#declare Wide = spline { 0, <1,2> 1, <3,4,5,6> }
#declare Value = Wide(0.5);
Check((Value.x = 2 & Value.y = 3 & Value.z = 2.5 & Value.t = 3), "points padded to the widest")
// A point at a parameter already used replaces it; points may come in any order.
#declare Replaced = spline { 1, <1,1,1> 0, <0,0,0> 2, <3,3,3> 1, <7,7,7> }
Check(Near(Replaced(0.5), <3.5,3.5,3.5>), "a repeated parameter replaces its point")
// ... except a repeat of the last parameter (of two or more points), which is dropped.
#declare Kept = spline { 0, <0,0> 1, <1,1> 1, <5,5> 2, <2,2> }
Check((Near(Kept(0.5), <0.5,0.5>) & Near(Kept(1.5), <1.5,1.5>)), "a repeat of the last parameter is dropped")
#declare Single = spline { 0, <0,0> 0, <9,9> 0, <8,8> }
Check(Near(Single(0), <8,8>), "a single point is replaced")
// Too few points for a kind: straight segments.
#declare Two = spline { natural_spline 0, <1,2,3> 1, <2,2,2> }
Check(Near(Two(0.5), <1.5,2,2.5>), "two points interpolate linearly")
#declare One = spline { cubic_spline 0, <1,2,3> }
Check(Near(One(7), <1,2,3>), "one point is constant")
// Splines pass to macros like any identifier.
#macro AtTwo(S) #local V = S(2); V.y #end
Check((abs(AtTwo(Points) - 1.333333333) < 1e-8), "a spline passed to a macro")
// Points can come from loops.
#declare Looped = spline {
  linear_spline
  #for (I, 0, 4) I, <I, I*I, 0> #end
}
Check(Near(Looped(2.5), <2.5,6.5,0>), "points from a #for loop")
// A parameter that is not a number gives the first point (it never crashes).
#declare NanCubic = spline { cubic_spline 0, <0,0>, 1, <1,1>, 2, <2,4>, 3, <3,9> }
#declare NanOne = spline { linear_spline 0, <5,6> }
#declare NanValue = val("nan");
#declare A = NanCubic(NanValue);
#declare B = NanOne(NanValue);
#if (B.x != 5 | B.y != 6) #error "one-point spline at NaN" #end
