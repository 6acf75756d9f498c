// error: 5:10 undefined identifier `locaton`
// error-text: did you mean `location`?
// POV-Ray: Parse Error: No matching } in 'camera', undeclared identifier 'locaton' found instead
// Mistake: camera `location` misspelt `locaton`
camera { locaton <0, 1, -5> look_at 0 }
