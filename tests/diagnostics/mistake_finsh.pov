// error: 7:3 unknown block keyword `finsh`
// error-text: did you mean `finish`?
// POV-Ray: Parse Error: No matching } in 'sphere', undeclared identifier 'finsh' found instead
// Mistake: `finish` misspelt `finsh`
sphere { 0, 1
  pigment { rgb 1 }
  finsh { phong 1 }
}
