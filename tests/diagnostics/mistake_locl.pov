// error: 6:4 in the text this macro produced: unknown directive `#locl`
// error-text: did you mean `#local`?
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'locl' found instead
// Mistake: `#local` misspelt `#locl`
#macro Ball()
  #locl R = 1;
  sphere { 0, R }
#end
Ball()
