#macro Bad(V)
  #local Q = V + "x";
#end
#macro Rows(N)
  #if (N > 0) union { #end
  #for (I, 1, N)
    Bad(I)
  #end
  #if (N > 0) } #end
#end
object { Rows(2) }
