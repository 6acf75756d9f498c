// error: 4:25 `global_lights` is not allowed inside `union`

// global_lights belongs to light_group only
union { sphere { 0, 1 } global_lights }
