// Arithmetic, precedence, promotion and member access, as POV-Ray 3.7 evaluates them.
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#declare Eps = 1e-9;
Check(2*3-4/2+1 = 5, "precedence of * / over + -")
Check(-2*-3 = 6, "unary minus binds tighter than *")
Check(2 - -3*2 = 8, "unary minus inside a product")
Check(!0 + 1 = 2, "logical not binds tighter than +")
Check(-<1,2,3>.x = -1, "member access binds tighter than unary minus")
Check((1 + 2 > 2 ? 5 : 6) = 5, "conditional inside parentheses")
Check((1 = 1 & 0 | 1) = 1, "& and | left to right after relations")
#declare V = <1,2,3>*2 + 1;
Check(V.x = 3 & V.y = 5 & V.z = 7, "float promotes to vector")
Check(vlength(<3,4,0>) = 5, "vlength")
Check(vdot(x, y) = 0, "vdot")
#declare C = vcross(x, y);
Check(C.z = 1, "vcross x y = z (left-handed)")
Check(abs(sin(pi/2) - 1) < Eps, "sin and pi")
Check(mod(7, 3) = 1 & div(7, 2) = 3 & int(-2.5) = -2 & floor(-2.5) = -3, "integer functions")
Check(min(3, 1, 2) = 1 & max(3, 1, 2) = 3, "min and max take several arguments")
Check(abs(degrees(radians(90)) - 90) < Eps, "degrees and radians")
Check(abs(pow(2, 10) - 1024) < Eps & abs(sqrt(16) - 4) < Eps, "pow and sqrt")
Check(abs(atan2(1, 1) - pi/4) < Eps, "atan2")
#declare R = vrotate(x, <0, 90, 0>);
Check(abs(R.z + 1) < Eps, "rotate x by 90 about y gives -z")
#declare Col = rgb <0.1, 0.2, 0.3>;
Check(abs(Col.green - 0.2) < Eps & Col.filter = 0, "rgb colour components")
#declare Col2 = color red 1 green 0.5 filter 0.25;
Check(Col2.red = 1 & Col2.green = 0.5 & Col2.blue = 0 & Col2.filter = 0.25, "colour component keywords")
#declare Col3 = rgbft <1, 1, 1, 0.5, 0.25> * 0.5;
Check(Col3.transmit = 0.125, "colour times float scales all five components")
Check(true & yes & on & !false & !no & !off, "boolean constants")
Check(t.t = 1 & u.u = 1 & v.v = 1, "t u v constants")
#declare W = < -1 0 2 >;
Check(W.x = -1 & W.z = 2, "vector without commas")
Check(select(-1, 1, 2) = 1 & select(1, 1, 2) = 2 & select(0, 1, 2, 3) = 2, "select")
Check(bitwise_and(6, 3) = 2 & bitwise_or(4, 1) = 5 & bitwise_xor(3, 1) = 2, "bitwise functions")
// rand follows POV-Ray 3.7's own sequence (values printed by povray 3.7).
#declare S = seed(0);
Check(abs(rand(S) - 0.000002874294) < 1e-11, "first value of seed(0)")
Check(abs(rand(S) - 0.466563684509) < 1e-11, "second value of seed(0)")
Check(abs(rand(S) - 0.249070228834) < 1e-11, "third value of seed(0)")
#declare S2 = seed(-1);
Check(abs(rand(S2) - 0.578012873553) < 1e-11, "negative seeds wrap")
#declare S3 = seed(2.7);
Check(abs(rand(S3) - 0.843982876242) < 1e-11, "seeds are truncated")
// User-defined functions.
#declare Square = function(A) { A * A }
#declare Dist = function { sqrt(x*x + y*y + z*z) }
#declare Both = function(P, Q) { Square(P) + Square(Q) }
Check(Square(3) = 9, "function with a parameter")
Check(Dist(3, 4, 0) = 5, "function with the default x, y, z parameters")
Check(Both(1, 2) = 5, "functions call functions")
#declare Step = function(A) { select(A, 0, 1) }
Check(Step(-2) = 0 & Step(2) = 1, "select inside a function")
// Geometry queries (values printed by povray 3.7 for the same objects).
#declare Ball = sphere { <1, 2, 3>, 1 scale 2 }
#declare Low = min_extent(Ball);
#declare High = max_extent(Ball);
Check(vlength(Low - <0, 2, 4>) < 1e-6 & vlength(High - <4, 6, 8>) < 1e-6, "min_extent and max_extent (bounds are padded by a tiny epsilon)")
#declare Turned = box { 0, 1 rotate 45*y }
Check(abs(max_extent(Turned).x - sqrt(2)) < 1e-6 & abs(max_extent(Turned).z - sqrt(0.5)) < 1e-6, "extent of a rotated box")
Check(max_extent(plane { y, 0 }).x = 1e10, "unbounded objects reach 1e10")
#declare Normal = <9, 9, 9>;
#declare Hit = trace(Ball, <2, 4, -10>, z, Normal);
Check(vlength(Hit - <2, 4, 4>) < 1e-9 & vlength(Normal - <0, 0, -1>) < 1e-9, "trace returns the hit and its normal")
#declare Miss = trace(Ball, <20, 4, -10>, z, Normal);
Check(vlength(Miss) = 0 & vlength(Normal) = 0, "a missed trace gives zero vectors")
// The old colour syntax without `color`: component keywords alone make a colour, and in a
// pigment or a colour map entry they modify the colour before them (values from povray 3.7,
// whose pigment functions give single-precision results).
#declare OldColour = red 1 green 0.5;
Check(OldColour.red = 1 & OldColour.green = 0.5 & OldColour.blue = 0, "components alone")
#declare QuickColoured = function { pigment { rgb <0.1, 0.2, 0.3> quick_color red 0.95 green 0.62 } }
#declare QuickSample = QuickColoured(0, 0, 0);
Check(abs(QuickSample.green - 0.2) < 1e-6, "quick_color red .. green ..")
#declare Modified = function { pigment { rgb <0.2, 0.4, 0.6> green 0.8 } }
#declare ModifiedSample = Modified(0, 0, 0);
Check(abs(ModifiedSample.green - 0.8) < 1e-6 & abs(ModifiedSample.blue - 0.6) < 1e-6, "pigment component modifies")
#declare OldMap = function { pigment { gradient x color_map { [0 red 1 green 0.5] [1 rgb <0, 0, 1> red 0.5] } } }
#declare Halfway = OldMap(0.5, 0, 0);
Check(abs(Halfway.red - 0.75) < 1e-6 & abs(Halfway.green - 0.25) < 1e-6 & abs(Halfway.blue - 0.5) < 1e-6, "old colours in a colour map")

// Division by zero: POV-Ray warns and goes on with positive infinity, whatever the sign of
// the numerator (measured: 5/0, -5/0, 0/0 and each component of <5,-5,0>/0 print inf).
#declare DivZero = 0;
#declare PosInf = 5/DivZero;
Check(PosInf > 1e300 & -5/DivZero > 1e300 & 0/DivZero > 1e300, "x/0 is +infinity")
#declare InfVector = <5, -5, 0>/DivZero;
Check(InfVector.x > 1e300 & InfVector.y > 1e300 & InfVector.z > 1e300, "<..>/0 is +infinity")
// Infinity minus infinity is no number: =, <= and >= then hold and != does not (measured).
Check(PosInf = PosInf & PosInf <= PosInf & PosInf >= PosInf & !(PosInf != PosInf), "inf = inf")
Check(!(PosInf = 5) & PosInf != 5 & !(PosInf < PosInf), "inf is no finite number")
