sphere { 0, 1
  pigmnet { rgb 1 }
}
