// error: 5:24 undefined identifier `reflexion`
// error-text: did you mean `reflection`?
// POV-Ray: Parse Error: No matching } in 'finish', undeclared identifier 'reflexion' found instead
// Mistake: `reflection` misspelt `reflexion`
sphere { 0, 1 finish { reflexion 0.3 } }
