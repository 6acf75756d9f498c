// error: 6:20 in the text this macro produced: unclosed `{`
// error-text: in macro `Open`, called at
// error-text: text_macro_unbalanced.pov:9:10

#macro Open(Flag)
  #if (Flag) union { #else merge { #end
    sphere { 0, 1 }
#end
object { Open(true) }
