// error: 5:25 undefined identifier `colr`
// error-text: did you mean `color`?
// POV-Ray: Parse Error: No matching } in 'pigment', undeclared identifier 'colr' found instead
// Mistake: `color` misspelt `colr` in a pigment
sphere { 0, 1 pigment { colr rgb 1 } }
