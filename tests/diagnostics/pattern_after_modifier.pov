sphere { 0, 1
  pigment { scale 2 checker rgb 1, rgb 0 }
}
