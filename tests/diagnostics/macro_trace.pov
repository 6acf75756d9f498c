#macro Inner(V)
  #local Q = V + "x";
  Q
#end
#macro Outer()
  Inner(1)
#end
#declare Z = Outer();
