// error: 5:32 a `>` without its `<`
// error-text: a vector is written `<1, 2, 3>`
// POV-Ray: Parse Error: No matching } in 'sphere', ,  found instead
// Mistake: vector without its opening `<`
sphere { 0, 1 translate 1, 2, 3> }
