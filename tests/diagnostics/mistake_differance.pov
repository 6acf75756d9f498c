// error: 5:1 unknown block keyword `differance`
// error-text: did you mean `difference`?
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'differance' found instead
// Mistake: `difference` misspelt `differance`
differance {
  box { -1, 1 }
  sphere { 0, 1.2 }
}
