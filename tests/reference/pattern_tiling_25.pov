// The `tiling 25` pattern (Penrose's pentagons, stars, boats and diamonds) seen from
// above, through a colour map that shows all six tile types and their bevels: left, round
// the origin (the centre of the tiling's five-fold symmetry); right, a stretch 1000 units
// out.
camera { orthographic location <0, 10, 0> look_at 0 right x*8 up z*6 }
light_source { <0, 20, 0> rgb 1 }
#declare Ramp = color_map { [0 rgb <0.1, 0.1, 0.4>] [1/6 rgb <0.2, 0.5, 0.9>] [2/6 rgb <0.1, 0.6, 0.3>] [3/6 rgb <1, 0.8, 0.2>] [4/6 rgb <0.9, 0.4, 0.1>] [5/6 rgb <0.6, 0.1, 0.5>] [1 rgb <1, 1, 1>] }
box {
  <-1.95, -1, -2.9>, <1.95, 0, 2.9>
  pigment { tiling 25 color_map { Ramp } scale 0.6 }
  finish { ambient 1 diffuse 0 }
  translate <2, 0, 0>
}
box {
  <-1.95, -1, -2.9>, <1.95, 0, 2.9>
  pigment { tiling 25 color_map { Ramp } translate <-731.5, 0, 682.25> scale 0.6 }
  finish { ambient 1 diffuse 0 }
  translate <-2, 0, 0>
}
