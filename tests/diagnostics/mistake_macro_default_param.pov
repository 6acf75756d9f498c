// error: 5:15 macro parameters cannot have default values
// error-text: POV-Ray has no default values: write `#macro Ball(R)` and pass the value in every call
// POV-Ray: Parse Error: Expected 'identifier or expression.', = found instead
// Mistake: default parameter value in a `#macro` (not POV-Ray syntax)
#macro Ball(R = 1)
  sphere { 0, R }
#end
