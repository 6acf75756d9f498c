// error: 6:1 `#else` without an `#if`
// error-text: `#else` belongs between `#if (Condition)` and its `#end`
// POV-Ray: Parse Error: Mis-matched '#else'.
// Mistake: `#else` without `#if`
sphere { 0, 1 }
#else
box { 0, 1 }
