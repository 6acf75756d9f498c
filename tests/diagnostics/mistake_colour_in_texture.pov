// error: 5:25 a value is not allowed inside `texture`
// (durer prints no help line)
// POV-Ray: Parse Error: Keyword 'color' can only be used in a pigment or density statement.
// Mistake: colour written directly in a texture
sphere { 0, 1 texture { rgb <1, 0, 0> } }
