// error: 6:18 unmatched `]`
// error-text: remove it, or add the `[` it should close
// POV-Ray: Parse Error: No matching } in 'sphere', ] found instead
// Mistake: an extra `]` after an array index
#declare Ar = array[2] { 1, 2 };
sphere { 0, Ar[1]] }
