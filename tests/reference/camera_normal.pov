// camera_normal: a camera `normal { }` bends every ray as if its direction were a surface
// normal, with the pattern evaluated at the image point <u, v, 0> (u, v in -0.5..0.5);
// the camera's own transformations do not move the pattern
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 0, -5> look_at <0, 0, 0>
  normal { wood 0.4 scale 0.3 translate <0.05, 0.1, 0> }
  rotate z*20
}
light_source { <0, 0, -10> rgb 1 }
plane { z, 0
  pigment { checker rgb <1, 0.2, 0.1> rgb <0.1, 0.3, 1> scale 0.5 }
  finish { ambient 1 diffuse 0 }
}
