light_source { <0, 5, 0> rgb 1
  jitter circular }
