// error: 6:8 `#ifdef` needs parentheses around the name
// error-text: write `#ifdef (A)`
// POV-Ray: Parse Error: Expected '(', float function 'float identifier' found instead
// Mistake: `#ifdef` without parentheses
#declare A = 1;
#ifdef A
  sphere { 0, A }
#end
