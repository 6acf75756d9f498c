// error: 6:13 unclosed `<`
// error-text: add the matching `>`
// POV-Ray: Parse Error: Expected '>', } found instead
// Mistake: vector without its closing `>`
sphere { 0, 1
  translate <1, 2, 3
}
