// error: 6:25 `T` is not allowed inside `pigment`
// (durer prints no help line)
// POV-Ray: Parse Error: No matching } in 'pigment', texture identifier found instead
// Mistake: texture identifier used as a pigment
#declare T = texture { pigment { rgb 1 } }
sphere { 0, 1 pigment { T } }
