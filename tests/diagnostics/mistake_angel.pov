// error: 5:40 undefined identifier `angel`
// error-text: did you mean `angle`?
// POV-Ray: Parse Error: No matching } in 'camera', undeclared identifier 'angel' found instead
// Mistake: camera `angle` misspelt `angel`
camera { location <0, 1, -5> look_at 0 angel 40 }
