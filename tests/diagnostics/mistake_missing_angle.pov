// error: 7:1 expected an expression, found `}`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected '>', } found instead
// Mistake: vector without its closing `>`
sphere { 0, 1
  translate <1, 2, 3
}
