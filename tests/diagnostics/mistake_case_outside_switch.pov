// error: 5:2 expected a directive, block or value, found `case`
// (durer prints no help line)
// POV-Ray: Parse Error: Mis-matched '#case' or '#range'.
// Mistake: `#case` without `#switch`
#case (1)
  sphere { 0, 1 }
#break
