// error: 5:47 `uv_mapping` must come before the object's texture
// error-text: write it before `texture`, `pigment` and `normal`

// POV-Ray refuses this too: "uv_mapping must be specified before texture".
sphere { 0, 1 pigment { checker rgb 1 rgb 0 } uv_mapping }
