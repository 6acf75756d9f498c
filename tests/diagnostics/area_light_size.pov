// error: 5:36 an area light needs 1 to 257 lights per axis
// error-text: this is 0

light_source { <0, 5, 0> rgb 1
  area_light <1, 0, 0>, <0, 0, 1>, 0, 4 }
