// error: 5:15 undefined identifier `scael`
// error-text: did you mean `scale`?
// POV-Ray: Parse Error: No matching } in 'sphere', undeclared identifier 'scael' found instead
// Mistake: `scale` misspelt `scael`
sphere { 0, 1 scael 2 }
