// The `tiling` pattern, tilings 11 to 18 on eight squares seen from above, through a
// colour map that shows every tile type and its bevel.
camera { orthographic location <0, 10, 0> look_at 0 right x*8 up z*6 }
light_source { <0, 20, 0> rgb 1 }
#declare Ramp = color_map { [0 rgb <0.1, 0.1, 0.4>] [0.5 rgb <1, 0.8, 0.2>] [1 rgb <0.9, 0.2, 0.1>] }
#for (N, 11, 18)
  box {
    <-0.95, -1, -1.4>, <0.95, 0, 1.4>
    pigment { tiling N color_map { Ramp } scale 0.4 }
    finish { ambient 1 diffuse 0 }
    translate <-3 + 2 * mod(N - 11, 4), 0, (N <= 14 ? 1.5 : -1.5)>
  }
#end
