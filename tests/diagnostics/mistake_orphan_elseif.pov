// error: 6:1 `#elseif` without an `#if`
// error-text: `#elseif` belongs between `#if (Condition)` and its `#end`
// POV-Ray: Parse Error: Mis-matched '#elseif'.
// Mistake: `#elseif` without `#if`
#declare A = 1;
#elseif (A > 0)
  sphere { 0, 1 }
