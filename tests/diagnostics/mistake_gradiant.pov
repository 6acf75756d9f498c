// error: 5:25 undefined identifier `gradiant`
// error-text: did you mean `gradient`?
// POV-Ray: Parse Error: No matching } in 'pigment', undeclared identifier 'gradiant' found instead
// Mistake: `gradient` misspelt `gradiant`
sphere { 0, 1 pigment { gradiant y } }
