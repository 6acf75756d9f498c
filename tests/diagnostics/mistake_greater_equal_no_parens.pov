// error: 6:18 `>=` outside parentheses
// error-text: as in POV-Ray, write `(A >= 1)`: comparisons, `&`, `|` and `? :` need parentheses around them
// POV-Ray: Parse Error: All #declares of float, vector, and color require semi-colon ';' at end if the language version is set to 3.5 or higher. Either add the semi-colon or set the language version to 3.1 or lower.
// Mistake: `>=` outside parentheses in a `#declare`
#declare A = 2;
#declare Big = A >= 1;
