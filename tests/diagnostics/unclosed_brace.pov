sphere { <0, 0, 0>, 1
  pigment { rgb 1 }

box { 0, 1 }
