// error: 5:13 unexpected `}`
// error-text: a block is written `sphere { ... }`
// POV-Ray: Parse Error: Missing { after 'sphere', float function 'float constant' found instead
// Mistake: object without its opening `{`
sphere 0, 1 }
