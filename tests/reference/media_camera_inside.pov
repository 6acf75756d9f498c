// media_camera_inside: the camera sits inside a hollow sphere of scattering media, so camera
// rays start inside it and cross its media from their first step (POV-Ray finds the objects
// around the camera before tracing); the box and floor are seen through the media
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -5> look_at <0, 0.5, 0> }
light_source { <2, 6, -1> rgb 1.5 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.3 } }
box { -1, 1 rotate y * 30 pigment { rgb <1, 0.4, 0.2> } }
sphere { 0, 12 hollow
  pigment { rgbt 1 }
  interior { media { scattering { 1, 0.012 } absorption 0.01 method 3 } }
}
