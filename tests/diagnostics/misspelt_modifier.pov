sphere { 0, 1 tranlate x }
