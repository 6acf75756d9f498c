// error: 5:16 POV-Ray has no `%` operator
// error-text: write the remainder with `mod`: `mod(5, 2)`
// POV-Ray: Parse Error: All #declares of float, vector, and color require semi-colon ';' at end if the language version is set to 3.5 or higher. Either add the semi-colon or set the language version to 3.1 or lower.
// Mistake: `%` for modulo (POV-Ray has `mod`)
#declare A = 5 % 2;
