// error: 5:1 unknown block keyword `unoin`
// error-text: did you mean `union`?
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'unoin' found instead
// Mistake: `union` misspelt `unoin`
unoin {
  sphere { 0, 1 }
  sphere { x, 1 }
}
