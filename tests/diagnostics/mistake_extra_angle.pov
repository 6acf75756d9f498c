// error: 5:38 an extra `>`
// error-text: remove it: the vector before it is already closed
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: an extra `>` after a vector
sphere { 0, 1 pigment { rgb <1, 0, 0>> } }
