// error: 5:21 unmatched `)`
// error-text: remove it, or add the `(` it should close
// POV-Ray: Parse Error: All #declares of float, vector, and color require semi-colon ';' at end if the language version is set to 3.5 or higher. Either add the semi-colon or set the language version to 3.1 or lower.
// Mistake: an extra `)` in an expression
#declare A = (1 + 2));
