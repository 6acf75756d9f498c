// durer showcase: CSG, glass, a mirror, coloured shadows and a spotlight.
// Render: cargo run --release -- render examples/showcase.pov --width 640 --height 480
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }

camera { location <0, 3.2, -7.5> look_at <0, 0.8, 0> angle 55 }
light_source { <-6, 10, -8> rgb 1 }
light_source { <5, 6, -2> rgb <0.5, 0.45, 0.4> spotlight point_at <1.5, 0, 0> radius 18 falloff 30 }
background { rgb <0.55, 0.7, 0.95> }

#declare Floor = texture {
  pigment { checker rgb <0.9, 0.88, 0.82>, rgb <0.18, 0.2, 0.25> scale 1.5 }
  finish { diffuse 0.8 reflection 0.08 }
}
plane { y, 0 texture { Floor } }

// A cube with a spherical bite and a drilled hole.
difference {
  box { -1, 1 }
  sphere { <1, 1, -1>, 1.1 }
  cylinder { <0, 0, -2>, <0, 0, 2>, 0.35 }
  pigment { rgb <0.85, 0.25, 0.15> }
  finish { phong 0.6 phong_size 60 }
  rotate 20*y
  translate <-2.3, 1, 0.5>
}

// A glass sphere over the checker floor.
sphere {
  <0, 1, -0.8>, 1
  pigment { rgbf <0.95, 1, 0.97, 0.92> }
  finish { ambient 0 diffuse 0.05 specular 0.8 roughness 0.005 reflection 0.06 }
  interior { ior 1.5 }
}

// A mirror ball and a lens (intersection of two spheres).
sphere { <2.4, 0.9, 1.2>, 0.9 pigment { rgb 0.05 } finish { reflection 0.85 specular 0.6 } }
intersection {
  sphere { <0, 0, -0.6>, 1 }
  sphere { <0, 0, 0.6>, 1 }
  pigment { rgb <0.2, 0.6, 0.3> }
  finish { specular 0.5 roughness 0.02 }
  rotate <0, -30, 0>
  translate <0.3, 0.5, 2.6>
}

// A torus ring and a cone.
torus { 0.6, 0.18 pigment { rgb <0.9, 0.75, 0.2> } finish { phong 0.8 metallic } translate <1.6, 0.18, -2> }
cone { <-0.9, 0, -2.6>, 0.45, <-0.9, 1.2, -2.6>, 0 pigment { gradient y color_map { [0 rgb <0.2, 0.3, 0.9>] [1 rgb <0.9, 0.9, 1>] } } }
