// global_lights belongs to light_group only
union { sphere { 0, 1 } global_lights }
