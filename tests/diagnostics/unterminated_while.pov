#while (1)
  #declare A = 1;
