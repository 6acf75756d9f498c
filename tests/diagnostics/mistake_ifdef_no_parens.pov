// error: 6:2 expected a directive, block or value, found `ifdef`
// error-text: did you mean `ifndef`?
// POV-Ray: Parse Error: Expected '(', float function 'float identifier' found instead
// Mistake: `#ifdef` without parentheses
#declare A = 1;
#ifdef A
  sphere { 0, A }
#end
