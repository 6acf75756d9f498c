// error: 5:13 macro parameters go in parentheses
// error-text: write `#macro Ball(R)`
// POV-Ray: Parse Error: Expected 'identifier or expression.', undeclared identifier 'R' found instead
// Mistake: `#macro` parameters without parentheses
#macro Ball R
  sphere { 0, R }
#end
