// warning: 4:10 `circular` only affects an area light; it is ignored

light_source { <0, 5, 0> rgb 1
  jitter circular }
