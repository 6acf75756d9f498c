// error: 6:55 expected `,`, a block or something else, found `}`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected ']', } found instead
// Mistake: a color_map entry without its closing `]`
sphere { 0, 1
  pigment { gradient y color_map { [0 rgb 0] [1 rgb 1 } }
}
