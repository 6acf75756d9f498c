height_field { pot "images/palette8.png" }
