// Random placement with seed and rand: must land exactly where POV-Ray puts it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -8> look_at <0, 0, 0> angle 55 }
light_source { <5, 10, -5> rgb 1 }
plane { y, 0 pigment { rgb 0.75 } }

#declare Stream = seed(2024);
#for (I, 1, 60)
  #local Position = <rand(Stream) * 8 - 4, 0, rand(Stream) * 8 - 4>;
  #local Size = 0.1 + 0.25 * rand(Stream);
  sphere {
    Position + Size * y, Size
    pigment { rgb <rand(Stream), rand(Stream), rand(Stream)> }
    finish { phong 0.4 }
  }
#end
