// error: 6:20 expected `,`, a block or something else, found `\`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'second' found instead
// Mistake: a `#debug` string whose quote is never closed, over several lines
#debug "first line\n
#debug "second line\n"
sphere { 0, 1 }
