// error: 5:1 unknown directive `#delcare`
// error-text: did you mean `#declare`?
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'delcare' found instead
// Mistake: `#declare` misspelt `#delcare`
#delcare R = 1;
