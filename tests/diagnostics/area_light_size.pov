light_source { <0, 5, 0> rgb 1
  area_light <1, 0, 0>, <0, 0, 1>, 0, 4 }
