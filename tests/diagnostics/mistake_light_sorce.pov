// error: 5:1 unknown block keyword `light_sorce`
// error-text: did you mean `light_source`?
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'light_sorce' found instead
// Mistake: `light_source` misspelt `light_sorce`
light_sorce { <0, 5, -5> rgb 1 }
