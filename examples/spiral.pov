// A loop-generated spiral of spheres with a gradient of colours.
// Render: cargo run --release -- render examples/spiral.pov --width 640 --height 480
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 6, -11> look_at <0, 2, 0> angle 50 }
light_source { <8, 12, -10> rgb 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.65 } }

#declare Count = 120;
#for (I, 0, Count - 1)
  #local F = I / Count;
  #local Angle = F * 4 * 360;
  sphere {
    vrotate(<3 - 2 * F, 0.3 + 4 * F, 0>, <0, Angle, 0>), 0.25 + 0.15 * (1 - F)
    pigment { rgb <F, 0.4 + 0.4 * sin(F * pi), 1 - F> }
    finish { phong 0.7 phong_size 80 }
  }
#end
