// error: 8:14 cannot combine a float and a string
// error-text: in macro `Bad`, called at
// error-text: text_macro_call.pov:13:5
// error-text: in macro `Rows`, called at
// error-text: text_macro_call.pov:17:10

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
