// Tests: a `projected_through` object moves with its light: a lamp union (light inside a
// shade) placed twice lights the floor under each copy, and a light's own translate after
// `projected_through` moves the object too (a translate before it does not).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0, 0> }
light_source { <2, 8, -6>, rgb 0.3 }
#declare Shade = sphere { <0, 2, 0>, 0.4 pigment { rgbf <0.2, 0.5, 1, 0.9> } }
#declare Lamp = union {
  cylinder { <0, 0, 0>, <0, 1.6, 0>, 0.05 pigment { rgb <0.6, 0.4, 0.3> } }
  light_source { <0, 2, 0>, rgb <1, 0.8, 0.3>
    spotlight radius 25 falloff 40 tightness 0.5 point_at <0, 0, 0>
    projected_through { Shade } }
}
object { Lamp translate <-3, 0, 1> }
object { Lamp scale 0.8 translate <0, 0, 3> }
light_source { <0, 2, 0>, rgb <0.3, 0.8, 1>
  spotlight radius 20 falloff 35 point_at <0, 0, 0>
  projected_through { Shade } translate <3, 0, 0> }
light_source { <0, 2, 0>, rgb <1, 0.3, 0.3>
  spotlight radius 20 falloff 35 point_at <0, 0, 0>
  translate <1, 0, -2> projected_through { Shade translate <1, 0, -2> } }
box { <-0.3, 0, -0.3>, <0.3, 0.6, 0.3> rotate y*30 translate <1.5, 0, 0.5> pigment { rgb <0.8, 0.8, 0.2> } }
plane { y, 0 pigment { rgb 0.9 } }
