// The `tiling` pattern, tilings 19 to 24 (snub and dodecagon tilings) on six squares seen
// from above, through a colour map that shows every tile type and its bevel.
camera { orthographic location <0, 10, 0> look_at 0 right x*8 up z*6 }
light_source { <0, 20, 0> rgb 1 }
#declare Ramp = color_map { [0 rgb <0.1, 0.1, 0.4>] [0.5 rgb <1, 0.8, 0.2>] [1 rgb <0.9, 0.2, 0.1>] }
#for (N, 19, 24)
  box {
    <-1.25, -1, -1.4>, <1.25, 0, 1.4>
    pigment { tiling N color_map { Ramp } scale 0.3 }
    finish { ambient 1 diffuse 0 }
    translate <-2.65 + 2.65 * mod(N - 19, 3), 0, (N <= 21 ? 1.5 : -1.5)>
  }
#end
