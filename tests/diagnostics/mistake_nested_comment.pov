// error: 5:1 no `*/` closes this comment
// error-text: add `*/` where the comment ends (comments nest: each `/*` needs its own `*/`)
// POV-Ray: Parse Error: No */ closing comment found.
// Mistake: `/* */` comments nest: an inner `/*` leaves the outer one open
/* old code:
/* sphere { 0, 1 }
*/
sphere { 0, 1 }
