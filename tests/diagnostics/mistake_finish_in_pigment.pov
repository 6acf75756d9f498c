// error: 5:31 `finish { .. }` is not allowed inside `pigment`
// (durer prints no help line)
// POV-Ray: Parse Error: No matching } in 'pigment', finish found instead
// Mistake: finish inside a pigment
sphere { 0, 1 pigment { rgb 1 finish { phong 1 } } }
