// error: 5:24 undefined identifier `bumbs`
// error-text: did you mean `bumps`?
// POV-Ray: Parse Error: No matching } in 'normal', undeclared identifier 'bumbs' found instead
// Mistake: `bumps` misspelt `bumbs`
sphere { 0, 1 normal { bumbs 0.5 } }
