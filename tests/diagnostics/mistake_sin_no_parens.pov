// error: 5:14 `sin` needs parentheses
// error-text: built-in functions take their arguments in parentheses: `sin(...)`
// POV-Ray: Parse Error: Expected '(', float function 'float constant' found instead
// Mistake: `sin` without parentheses
#declare B = sin 1;
