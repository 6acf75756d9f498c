// error: 7:17 undefined identifier `Radius`
// error-text: in macro `Wall`, called at
// error-text: text_macro_error.pov:10:10

#macro Wall(Open)
  #if (Open) union { #else merge { #end
    sphere { 0, Radius }
  }
#end
object { Wall(true) }
