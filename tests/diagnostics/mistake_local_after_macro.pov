// error: 9:13 undefined identifier `R`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', undeclared identifier 'R' found instead
// Mistake: `#local` from a macro used after the macro
#macro Setup()
  #local R = 2;
#end
Setup()
sphere { 0, R }
