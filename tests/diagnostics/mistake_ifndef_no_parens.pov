// error: 5:9 `#ifndef` needs parentheses around the name
// error-text: write `#ifndef (Radius)`
// POV-Ray: Parse Error: Expected '(', undeclared identifier 'Radius' found instead
// Mistake: `#ifndef` without parentheses
#ifndef Radius
  #declare Radius = 1;
#end
sphere { 0, Radius }
