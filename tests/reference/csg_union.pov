// Tests: union: a molecule of spheres and cylinders sharing one pigment, with one child
// overriding it, and a union declared once and placed twice with object { Ident }.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.5, -6> look_at <0, 0.9, 0> angle 50 }
light_source { <-4, 9, -7> rgb 1 }
background { rgb <0.2, 0.2, 0.3> }

plane { y, 0 pigment { rgb <0.7, 0.7, 0.7> } }
#declare Molecule = union {
  sphere { <0, 0, 0>, 0.5 }
  sphere { <1, 0.4, 0>, 0.3 pigment { rgb <0.9, 0.9, 0.9> } }
  sphere { <-1, 0.4, 0.2>, 0.3 pigment { rgb <0.9, 0.9, 0.9> } }
  cylinder { <0, 0, 0>, <1, 0.4, 0>, 0.1 }
  cylinder { <0, 0, 0>, <-1, 0.4, 0.2>, 0.1 }
  pigment { rgb <0.9, 0.2, 0.2> }
}
object { Molecule translate <-1.5, 1, 0> }
object { Molecule rotate y*90 translate <1.5, 0.8, 0.5> pigment { rgb <0.2, 0.4, 0.9> } }
union {
  box { <-0.5, 0, -0.5>, <0.5, 0.4, 0.5> }
  sphere { <0, 0.4, 0>, 0.4 }
  translate <0.3, 0, -1>
  pigment { rgb <0.9, 0.8, 0.3> }
}
