// error: 7:14 in macro `Inner`, called at
// error-text: macro_trace.pov:11:3
// error-text: in macro `Outer`, called at
// error-text: macro_trace.pov:13:14

#macro Inner(V)
  #local Q = V + "x";
  Q
#end
#macro Outer()
  Inner(1)
#end
#declare Z = Outer();
