// error: 5:2 expected a directive, block or value, found `macro`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'identifier or expression.', undeclared identifier 'R' found instead
// Mistake: `#macro` parameters without parentheses
#macro Ball R
  sphere { 0, R }
#end
