// error: 6:46 unclosed `[`
// error-text: add the matching `]`
// POV-Ray: Parse Error: Expected ']', } found instead
// Mistake: a color_map entry without its closing `]`
sphere { 0, 1
  pigment { gradient y color_map { [0 rgb 0] [1 rgb 1 } }
}
