// quartic (a torus written as a polynomial) with sturm.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, -1 pigment { rgb <0.8, 0.8, 0.7> } }
// torus R=1.5 r=0.5 as quartic
quartic {
  < 1, 0, 0, 0, 2, 0, 0, 2, 0, -5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 4, 0, 0, 0, 0, 1, 0, -5, 0, 4 >
  sturm
  pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.5 }
  translate <-1.2, 0, 0>
}
