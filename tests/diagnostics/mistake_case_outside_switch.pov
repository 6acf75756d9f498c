// error: 5:1 `#case` outside a `#switch`
// error-text: `#case` starts a branch of `#switch (Value) ... #end`
// POV-Ray: Parse Error: Mis-matched '#case' or '#range'.
// Mistake: `#case` without `#switch`
#case (1)
  sphere { 0, 1 }
#break
