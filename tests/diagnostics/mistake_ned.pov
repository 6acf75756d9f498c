// error: 5:1 unterminated `#if`
// error-text: did you mean `#end` instead of `#ned`?
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'ned' found instead
// Mistake: `#end` misspelt `#ned`
#if (1)
  sphere { 0, 1 }
#ned
