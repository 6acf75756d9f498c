// error: 6:8 `#while` needs parentheses around its condition
// error-text: write `#while (I < 3)`
// POV-Ray: Parse Error: Expected '(', float function 'float identifier' found instead
// Mistake: `#while` condition without parentheses
#declare I = 0;
#while I < 3
  #declare I = I + 1;
#end
