// error: 6:14 `A` is a float, not a function or macro
// error-text: only functions, macros and splines can be called; write `A` without the parentheses to use its value
// POV-Ray: Parse Error: All #declares of float, vector, and color require semi-colon ';' at end if the language version is set to 3.5 or higher. Either add the semi-colon or set the language version to 3.1 or lower.
// Mistake: a float called like a function
#declare A = 5;
#declare B = A(2);
