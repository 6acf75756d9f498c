// Pattern, pigment, transform and spline functions; expected values printed by POV-Ray 3.7
// (`#debug` of the same calls; POV-Ray keeps colours and noise in single precision, hence
// the tolerances).
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#macro Near(A, B, Tolerance) (abs((A) - (B)) <= Tolerance) #end

// A pigment function returns five components; members pick them inside other functions.
#declare P = function { pigment { gradient x color_map { [0 rgbft <0,0.25,0.5,0.125,0.5>] [1 rgbft <1,0.75,0.25,0.625,0>] } } }
#declare Pc = P(0.25, 3, 4);
Check((Pc.red = 0.25 & Pc.green = 0.375 & Pc.blue = 0.4375 & Pc.filter = 0.25 & Pc.transmit = 0.375), "pigment function called from scene code")
Check((P(0.25, 0, 0).gray = 0.297 * 0.25 + 0.589 * 0.375 + 0.114 * 0.4375), "a member of a pigment function call in scene code")
#declare F = function { P(x,y,z).gray + P(x,y,z).blue * 10 + P(x, y, z).hf*100 + P(x,y,z).transmit*1000 + P(x,y,z).filter*10000 }
Check(Near(F(0.25, 0, 0), 2904.768809264706, 1e-9), ".gray .blue .hf .transmit .filter inside a function")
#declare Crack = function { pigment { crackle scale 0.5 color_map { [0 rgb 0] [1 rgb 1] } } }
Check(Near(Crack(0.3, 0.4, 0.6).red, 0.245224431157, 1e-8), "a crackle pigment function")

// A pattern function returns the pattern's value after its modifiers; block patterns give
// their block index.
#declare B = function { pattern { bozo scale 0.3 turbulence 0.5 warp { repeat x*0.7 } } }
Check((Near(B(0.1,0.2,0.3), 0.572494092648, 1e-8) & Near(B(1.1,0.2,0.3), 0.638277976288, 1e-8)), "bozo with turbulence and a repeat warp")
#declare W = function { pattern { wood frequency 2 phase 0.1 sine_wave rotate 30*y } }
Check(Near(W(0.5,0.2,0.3), 0.018220377767, 1e-8), "wood with wave modifiers and a rotation")
#declare C = function { pattern { checker scale 0.5 } }
#declare H = function { pattern { hexagon } }
Check((C(0.25,0.25,0.25) = 0 & C(0.75,0.25,0.25) = 1), "checker blocks")
Check((H(0.5,0,0.5) = 0 & H(1.5,0,0.5) = 2 & H(0.9,0,0) = 0), "hexagon blocks")

// A transform function returns the transformed point.
#declare T = function { transform { rotate 90*z translate <1,2,3> } }
Check((vlength(T(1, 0, 0) - <1,3,3>) < 1e-12), "transform function")
#declare TI = function { transform { rotate 90*z translate <1,2,3> inverse } }
Check((vlength(TI(1, 3, 3) - <1,0,0>) < 1e-12), "inverse transform function")

// A spline function takes the parameter alone.
#declare S = spline { natural_spline 0, <0,1,2> 1, <2,3,6> 2, <4,4,4> 3, <1,0,1> }
#declare SF = function { spline { S } }
Check((vlength(SF(1.5) - <3.375, 3.95, 5.525>) < 1e-12), "spline function")
#declare G = function { SF(x).x * 100 + SF(y).z + T(x, y, z).y * 1000 }
Check(Near(G(0.5, 2.5, 1), 2589.95, 1e-9), "spline and transform members inside a function")

// Identifiers are bound where the function is written: a function passed to a macro can be
// called inside the function the macro returns, and a later #declare does not change it.
#macro Doubled(Fn) function { Fn(x, y, z) * 2 } #end
#declare Sq = function { x * x + y }
#declare D = Doubled(Sq)
Check((D(3, 1, 0) = 20), "a function passed to a macro")
#declare K = 1;
#declare KF = function { x + K }
#declare K = 2;
Check((KF(1, 0, 0) = 2), "a constant bound where the function is declared")

// A transform function made inside a macro from a transform parameter (transforms.inc's
// vtransform and vinv_transform work this way).
#macro Moved(Point, Trans)
  #local Fn = function { transform { Trans } }
  (Fn(Point.x, Point.y, Point.z))
#end
#macro MovedBack(Point, Trans)
  #local Fn = function { transform { Trans inverse } }
  (Fn(Point.x, Point.y, Point.z))
#end
#declare Placement = transform { rotate <10,20,30> scale <1,2,3> translate 1 }
#declare V = Moved(<1,2,3>, Placement);
Check((vlength(V - <2.067425379,5.578118965,9.281744243>) < 1e-8), "a transform function made in a macro")
Check((vlength(MovedBack(V, Placement) - <1,2,3>) < 1e-12), "its inverse")
