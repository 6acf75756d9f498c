// error: 5:15 POV-Ray has no `^` operator
// error-text: write powers with `pow`: `pow(2, 3)`
// POV-Ray: Parse Error: All #declares of float, vector, and color require semi-colon ';' at end if the language version is set to 3.5 or higher. Either add the semi-colon or set the language version to 3.1 or lower.
// Mistake: `^` for powers (POV-Ray has `pow`)
#declare A = 2^3;
