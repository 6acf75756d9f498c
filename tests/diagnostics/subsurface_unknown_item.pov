// error: 4:54 `ior` is not allowed inside `subsurface`
// A finish's subsurface block holds translucency and anisotropy only.
#version 3.7;
sphere { 0, 1 finish { subsurface { translucency 0.5 ior 1.5 } } }
