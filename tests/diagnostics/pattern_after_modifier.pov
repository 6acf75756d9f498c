// error: 5:21 the pattern `checker` must come first in its block
// error-text: this comes before it

sphere { 0, 1
  pigment { scale 2 checker rgb 1, rgb 0 }
}
