// error: 5:32 `normal { .. }` is not allowed inside `finish`
// (durer prints no help line)
// POV-Ray: Parse Error: No matching } in 'finish', normal found instead
// Mistake: normal inside a finish
sphere { 0, 1 finish { phong 1 normal { bumps 0.3 } } }
