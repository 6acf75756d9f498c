// error: 5:16 unclosed `(`
// error-text: add the matching `)`
// POV-Ray: Parse Error: Expected ')', pigment found instead
// Mistake: a call inside an object without its closing `)`
sphere { 0, max(1, 2
  pigment { rgb 1 }
}
