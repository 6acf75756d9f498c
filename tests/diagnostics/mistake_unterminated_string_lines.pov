// error: 5:8 this string runs over several lines: is its closing `"` missing?
// error-text: add the missing `"` where this string ends
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'second' found instead
// Mistake: a `#debug` string whose quote is never closed, over several lines
#debug "first line\n
#debug "second line\n"
sphere { 0, 1 }
