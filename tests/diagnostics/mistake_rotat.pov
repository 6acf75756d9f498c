// error: 5:12 undefined identifier `rotat`
// error-text: did you mean `rotate`?
// POV-Ray: Parse Error: No matching } in 'box', undeclared identifier 'rotat' found instead
// Mistake: `rotate` misspelt `rotat`
box { 0, 1 rotat y*45 }
