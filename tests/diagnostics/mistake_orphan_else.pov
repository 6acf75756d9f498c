// error: 6:2 expected a directive, block or value, found `else`
// (durer prints no help line)
// POV-Ray: Parse Error: Mis-matched '#else'.
// Mistake: `#else` without `#if`
sphere { 0, 1 }
#else
box { 0, 1 }
