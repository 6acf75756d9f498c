// error: 5:1 unterminated `#if`
// error-text: add `#end` where the directive's body ends
// POV-Ray: Parse Error: End of file reached but #end expected.
// Mistake: `#if` without `#end`
#if (1)
  sphere { 0, 1 }
