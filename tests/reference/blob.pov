// blob: sphere and cylinder components, strength keyword, negative strength, a scaled component, old component syntax.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.7, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
blob { threshold 0.6
  sphere { <-0.5, 0, 0>, 1, 1 }
  sphere { <0.5, 0, 0>, 1, strength 1 }
  sphere { <0, 0.8, 0>, 0.8, 1 scale <1, 1.3, 1> }
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } translate <-1.5, 0.8, 0.5> }
blob { threshold 0.5
  cylinder { <-0.8, 0, 0>, <0.8, 0.6, 0>, 0.6, 1.5 }
  sphere { <0.3, 0.2, 0>, 0.7, -1 }
  component 1, 0.8, <0.8, 1.0, 0>
  pigment { rgb <0.2, 0.5, 0.9> } translate <1.5, 0.6, 0.3> }
