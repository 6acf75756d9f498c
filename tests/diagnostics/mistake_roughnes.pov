// error: 5:37 undefined identifier `roughnes`
// error-text: did you mean `roughness`?
// POV-Ray: Parse Error: No matching } in 'finish', undeclared identifier 'roughnes' found instead
// Mistake: `roughness` misspelt `roughnes`
sphere { 0, 1 finish { specular 0.5 roughnes 0.01 } }
