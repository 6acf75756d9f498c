// error: 5:15 unknown block keyword `texure`
// error-text: did you mean `texture`?
// POV-Ray: Parse Error: No matching } in 'sphere', undeclared identifier 'texure' found instead
// Mistake: `texture` misspelt `texure`
sphere { 0, 1 texure { pigment { rgb 1 } } }
