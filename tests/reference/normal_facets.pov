// Tests: the facets normal pattern. Top row: `coords` on flat tiles (crackle cells of the
// point / size, each tilted by coords times the vector noise at its feature point; the bump
// amount is ignored; a transformed pattern). Bottom row: the `size` form on spheres (the
// normal snapped to the feature point of its crackle cell), default and larger sizes, one
// sphere squashed and the pattern rotated.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#macro Tile(Column, Normal)
  box { <-4 + Column * 2.7, 0.05, 0>, <-1.4 + Column * 2.7, 2.95, 1>
    pigment { rgb 0.8 }
    normal { Normal }
    finish { ambient 0.1 diffuse 0.9 specular 0.3 }
  }
#end
#macro Ball(Column, Normal)
  sphere { 0, 1.25
    pigment { rgb 0.8 }
    normal { Normal }
    finish { ambient 0.1 diffuse 0.9 specular 0.4 }
    translate <-2.7 + Column * 2.7, -1.5, 0>
  }
#end
Tile(0, normal { facets coords 0.5 })
Tile(1, normal { facets 3 coords 0.8 size 0.3 })
Tile(2, normal { facets coords 0.6 size 0.2 scale <1, 2, 1> rotate <20, 10, 30> })
Ball(0, normal { facets })
Ball(1, normal { facets size 0.25 })
object { Ball(2, normal { facets 2 size 0.15 rotate 30 * x }) scale <1, 0.7, 1> }
