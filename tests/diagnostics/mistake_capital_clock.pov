// error: 5:14 undefined identifier `Clock`
// error-text: did you mean `clock`?
// POV-Ray: Parse Error: Cannot assign uninitialized identifier.
// Mistake: `clock` written `Clock`
#declare T = Clock * 2;
