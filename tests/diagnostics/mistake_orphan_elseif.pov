// error: 6:2 expected a directive, block or value, found `elseif`
// error-text: did you mean `else`?
// POV-Ray: Parse Error: Mis-matched '#elseif'.
// Mistake: `#elseif` without `#if`
#declare A = 1;
#elseif (A > 0)
  sphere { 0, 1 }
