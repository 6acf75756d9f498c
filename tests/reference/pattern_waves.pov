// Tests: wave shapes, frequency and phase on gradient stripes, one per row: ramp (default),
// triangle, sine, scallop, cubic, poly 2.5, and a ramp with frequency -1.5 and phase 0.3.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#declare Map = color_map { [0 rgb <0.1, 0.1, 0.4>] [0.6 rgb <0.9, 0.5, 0.1>] [1 rgb <1, 1, 0.8>] }
#macro Row(Index, Pattern)
  box { <-4, 2.2 - Index * 0.8, 0>, <4, 2.9 - Index * 0.8, 1>
    pigment { Pattern }
    finish { ambient 0.3 diffuse 0.7 }
  }
#end
Row(0, pigment { gradient x color_map { Map } scale 1.5 })
Row(1, pigment { gradient x color_map { Map } triangle_wave scale 1.5 })
Row(2, pigment { gradient x color_map { Map } sine_wave scale 1.5 })
Row(3, pigment { gradient x color_map { Map } scallop_wave scale 1.5 })
Row(4, pigment { gradient x color_map { Map } cubic_wave scale 1.5 })
Row(5, pigment { gradient x color_map { Map } poly_wave 2.5 scale 1.5 })
Row(6, pigment { gradient x color_map { Map } frequency -1.5 phase 0.3 scale 1.5 })
