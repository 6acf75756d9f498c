// error: 5:1 unterminated `#macro`
// error-text: has no matching `#end`

#macro A() sphere { 0, 1 } #end
#macro B()
  sphere { 0, 1 }
