// error: 3:20 cannot read height field image "images/palette8.png": cannot decode

height_field { pot "images/palette8.png" }
