// error: 6:36 a value is not allowed inside `color_map`
// (durer prints no help line)
// POV-Ray: Parse Error: Must have at least one color in color map.
// Mistake: color_map entries without brackets
sphere { 0, 1
  pigment { gradient y color_map { 0 rgb 0  1 rgb 1 } }
}
