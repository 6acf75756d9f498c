// error: 6:24 unknown block keyword `color_mpa`
// error-text: did you mean `color_map`?
// POV-Ray: Parse Error: No matching } in 'pigment', undeclared identifier 'color_mpa' found instead
// Mistake: `color_map` misspelt `color_mpa`
sphere { 0, 1
  pigment { gradient y color_mpa { [0 rgb 0] [1 rgb 1] } }
}
