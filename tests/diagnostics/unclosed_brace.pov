// error: 4:8 unclosed `{`
// error-text: this `{` is never closed

sphere { <0, 0, 0>, 1
  pigment { rgb 1 }

box { 0, 1 }
