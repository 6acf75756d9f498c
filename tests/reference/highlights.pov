// Tests: highlights, side by side on dark spheres: phong (tight and broad phong_size),
// specular (small and large roughness), and phong with metallic (highlight takes the
// surface colour).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 55 }
light_source { <-3, 6, -8> rgb 1 }
background { rgb <0.05, 0.05, 0.08> }

plane { y, 0 pigment { rgb <0.5, 0.5, 0.5> } }
#declare Base = rgb <0.1, 0.15, 0.4>;
sphere { <-2.6, 0.6, 0>, 0.6 pigment { Base } finish { phong 0.9 phong_size 80 } }
sphere { <-1.3, 0.6, 0>, 0.6 pigment { Base } finish { phong 0.9 phong_size 5 } }
sphere { <0, 0.6, 0>, 0.6 pigment { Base } finish { specular 0.9 roughness 0.005 } }
sphere { <1.3, 0.6, 0>, 0.6 pigment { Base } finish { specular 0.9 roughness 0.1 } }
sphere { <2.6, 0.6, 0>, 0.6 pigment { rgb <0.8, 0.5, 0.1> }
  finish { phong 1 phong_size 30 metallic } }
