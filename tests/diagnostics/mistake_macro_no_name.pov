// error: 5:8 expected an identifier, found `(`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'undeclared identifier', ( found instead
// Mistake: `#macro` without a name
#macro (R)
  sphere { 0, R }
#end
