// Vector-valued functions: a pigment function shapes an isosurface and colours it through a
// function pattern; a spline function and a transform function make the floor's pattern.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.6, -3.6> look_at <0, 0.1, 0> }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.1, 0.1, 0.15> }

#declare Hills = function {
  pigment { bozo scale 0.45 color_map { [0 rgb <0, 0.2, 0.1>] [1 rgb <1, 0.6, 0.3>] } }
}
isosurface {
  function { y - Hills(x, 0, z).red * 0.7 }
  contained_by { box { <-1.2, -0.05, -1.2>, <1.2, 0.8, 1.2> } }
  max_gradient 4
  pigment {
    function { Hills(x, 0, z).gray * 1.6 }
    color_map { [0 rgb <0.15, 0.3, 0.7>] [0.5 rgb <0.3, 0.7, 0.25>] [1 rgb <1, 0.95, 0.85>] }
  }
  finish { ambient 0.15 diffuse 0.8 }
}

#declare Profile = spline { cubic_spline -1, <0, 0> 0, <0, 0.2> 1, <0, 1> 2, <0, 0.1> 3, <0, 0> }
#declare ProfileFn = function { spline { Profile } }
#declare Swirl = function { transform { rotate 35 * y scale <0.5, 1, 1> } }
plane {
  y, -0.1
  pigment {
    function { ProfileFn(abs(Swirl(x, y, z).x) - floor(abs(Swirl(x, y, z).x) / 2) * 2).y }
    color_map { [0 rgb <0.9, 0.85, 0.7>] [1 rgb <0.3, 0.25, 0.5>] }
  }
  finish { ambient 0.3
  }
}
