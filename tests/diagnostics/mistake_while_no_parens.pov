// error: 7:4 expected a directive, block or value, found `declare`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected '(', float function 'float identifier' found instead
// Mistake: `#while` condition without parentheses
#declare I = 0;
#while I < 3
  #declare I = I + 1;
#end
