// error: 5:15 undefined identifier `translte`
// error-text: did you mean `translate`?
// POV-Ray: Parse Error: No matching } in 'sphere', undeclared identifier 'translte' found instead
// Mistake: `translate` misspelt `translte`
sphere { 0, 1 translte <1, 0, 0> }
