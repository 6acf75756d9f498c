#macro Wall(Open)
  #if (Open) union { #else merge { #end
    sphere { 0, Radius }
  }
#end
object { Wall(true) }
