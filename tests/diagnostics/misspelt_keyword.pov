// error: 5:3 unknown block keyword `pigmnet`
// error-text: did you mean `pigment`?

sphere { 0, 1
  pigmnet { rgb 1 }
}
