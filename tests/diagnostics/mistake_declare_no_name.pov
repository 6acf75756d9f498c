// error: 5:10 `#declare` needs a name
// error-text: write `#declare Name = Value;`
// POV-Ray: Parse Error: Expected 'undeclared identifier', = found instead
// Mistake: `#declare` without a name
#declare = 1;
