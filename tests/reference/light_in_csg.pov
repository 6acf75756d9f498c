// light_in_csg: light sources inside a declared union move with it; each placed copy of
// the union adds its lights (iortest.pov's lamps rotated up with their union)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 50 }
#declare Lamp = union {
  light_source { <0, 0, -6> rgb 0.5 }
  sphere { <0, 0, -6>, 0.1 pigment { rgb 1 } }
  rotate 50*x
}
object { Lamp }
object { Lamp rotate 60*y translate <1, 0, 0> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.6 } }
union {
  light_source { <0, 0, 0> rgb <0.2, 0.2, 0.6> spotlight point_at <0, -1, 0> radius 10 falloff 20 }
  translate <1.8, 2, -1>
}
