// error: 4:20 cannot find height field image `no_such_height.png`
// error-text: searched: /

height_field { png "no_such_height.png" smooth }
