// error: 5:15 unknown block keyword `interor`
// error-text: did you mean `interior`?
// POV-Ray: Parse Error: No matching } in 'sphere', undeclared identifier 'interor' found instead
// Mistake: `interior` misspelt `interor`
sphere { 0, 1 interor { ior 1.5 } }
