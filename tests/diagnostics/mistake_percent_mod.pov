// error: 5:16 expected `,`, a block or something else, found `%`
// (durer prints no help line)
// POV-Ray: Parse Error: All #declares of float, vector, and color require semi-colon ';' at end if the language version is set to 3.5 or higher. Either add the semi-colon or set the language version to 3.1 or lower.
// Mistake: `%` for modulo (POV-Ray has `mod`)
#declare A = 5 % 2;
