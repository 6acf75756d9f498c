// error: 5:14 undefined identifier `sin`
// error-text: did you mean `asin`?
// POV-Ray: Parse Error: Expected '(', float function 'float constant' found instead
// Mistake: `sin` without parentheses
#declare B = sin 1;
