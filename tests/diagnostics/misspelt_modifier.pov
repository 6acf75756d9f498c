// error: 4:15 `tranlate`
// error-text: did you mean `translate`?

sphere { 0, 1 tranlate x }
