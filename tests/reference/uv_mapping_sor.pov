// uv_mapping on surfaces of revolution: u around the Y axis from +x towards +z; on the side
// v runs along the height, each segment an equal share whatever its length; on the caps v is
// the distance from the axis over the cap's radius (reversed on the top cap). Segments of
// unequal lengths, radii that grow and shrink, open and sturm sors, both caps in view, and
// gradients that show u and v themselves.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4.5, -8> look_at <0, 0, 0> angle 48 }
light_source { <-4, 9, -7> rgb 1 }
#declare Checker = texture {
  uv_mapping pigment { checker rgb <1, 0.5, 0.1>, rgb <0.1, 0.3, 0.8> scale 0.05 }
  finish { ambient 0.35 }
}
#declare U_ramp = texture {
  uv_mapping pigment { gradient x color_map { [0 rgb <0, 0, 0.2>] [1 rgb <1, 1, 0.3>] } }
  finish { ambient 0.6 diffuse 0.4 }
}
#declare V_ramp = texture {
  uv_mapping pigment { gradient y color_map { [0 rgb <0.2, 0, 0>] [1 rgb <0.3, 1, 1>] } }
  finish { ambient 0.6 diffuse 0.4 }
}
// Seven points: five segments of heights 0.3, 1.2, 0.5, 1.0 (the first and last points
// only set slopes).
sor { 7, <0, -2>, <0.6, -1.5>, <1.2, -1.2>, <0.3, 0>, <1.0, 0.5>, <0.5, 1.5>, <0.8, 1.8>
  texture { Checker } translate <-2.2, 0.2, 0.6> }
// Open, seen from below and above: the inside of the side shows.
sor { 6, <0.3, -1.5>, <0.9, -1.2>, <0.5, -1.0>, <0.8, 0.9>, <0.6, 1.0>, <0.6, 1.5> open sturm
  texture { Checker } rotate <-40, 20, 0> scale 0.8 translate <0.2, 0.3, 0.4> }
// Caps tilted towards the camera and away from it.
sor { 5, <0.5, -1.5>, <0.6, -1>, <1.0, -0.8>, <0.7, 0.6>, <0.4, 1.2>
  texture { U_ramp } rotate <-50, 0, 30> scale 0.8 translate <2.4, 0.6, 0.4> }
sor { 5, <0.5, -1.5>, <0.9, -0.6>, <0.4, -0.3>, <0.8, 0.5>, <0.4, 1.2>
  texture { V_ramp } rotate <120, 30, 0> scale 0.7 translate <-0.9, -0.7, -2.2> }
sor { 5, <0.5, -1.5>, <0.9, -0.6>, <0.4, -0.3>, <0.8, 0.5>, <0.4, 1.2>
  texture { V_ramp } rotate <-25, 0, 0> scale 0.7 translate <1.2, -0.6, -2.4> }
plane { y, -1.6 pigment { rgb 0.5 } }
