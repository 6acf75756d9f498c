// error: 5:13 undefined identifier `Raduis`
// error-text: did you mean `Radius`?

#declare Radius = 1;
sphere { 0, Raduis }
