// error: 5:1 unknown block keyword `cilinder`
// error-text: did you mean `cylinder`?
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'cilinder' found instead
// Mistake: `cylinder` misspelt `cilinder`
cilinder { 0, y, 0.5 }
