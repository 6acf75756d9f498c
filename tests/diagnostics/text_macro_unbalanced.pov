#macro Open(Flag)
  #if (Flag) union { #else merge { #end
    sphere { 0, 1 }
#end
object { Open(true) }
