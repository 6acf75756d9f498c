// error: 5:1 unknown block keyword `backround`
// error-text: did you mean `background`?
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'backround' found instead
// Mistake: `background` misspelt `backround`
backround { rgb 1 }
