// error: 5:28 expected a count
// POV-Ray requires both sample counts: `samples 400` alone does not parse.
#version 3.7;
global_settings {
  subsurface { samples 400 radiosity off }
}
sphere { 0, 1 finish { subsurface { translucency 0.5 } } }
