// error: 5:1 unknown block keyword `spehre`
// error-text: did you mean `sphere`?
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'spehre' found instead
// Mistake: `sphere` misspelt `spehre`
spehre { 0, 1 }
