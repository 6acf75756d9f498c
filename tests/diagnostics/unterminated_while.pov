// error: 4:1 unterminated `#while`
// error-text: has no matching `#end`

#while (1)
  #declare A = 1;
