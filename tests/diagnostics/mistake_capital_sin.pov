// error: 5:14 unknown function or macro `Sin`
// error-text: did you mean `sin`?
// POV-Ray: Parse Error: Cannot assign uninitialized identifier.
// Mistake: `sin` written `Sin` (keywords are lower case)
#declare A = Sin(1);
