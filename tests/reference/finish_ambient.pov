// Tests: finish ambient, diffuse and brilliance with a coloured global ambient_light: rows
// of spheres from pure ambient to pure diffuse, and increasing brilliance.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1, 0.8, 0.6> }

camera { location <0, 3, -8> look_at <0, 1, 0> angle 50 }
light_source { <6, 8, -6> rgb 1 }
background { rgb <0.1, 0.1, 0.1> }

plane { y, 0 pigment { rgb <0.5, 0.5, 0.5> } finish { ambient 0.05 diffuse 0.8 } }
#local Paint = pigment { rgb <0.6, 0.7, 0.9> };
sphere { <-2.4, 0.5, -1>, 0.5 pigment { Paint } finish { ambient 0.6 diffuse 0 } }
sphere { <-0.8, 0.5, -1>, 0.5 pigment { Paint } finish { ambient 0.3 diffuse 0.4 } }
sphere { <0.8, 0.5, -1>, 0.5 pigment { Paint } finish { ambient 0 diffuse 0.7 } }
sphere { <2.4, 0.5, -1>, 0.5 pigment { Paint } finish { ambient 0 diffuse 1 } }
sphere { <-2.4, 1.7, 1>, 0.5 pigment { Paint } finish { ambient 0 brilliance 0.3 } }
sphere { <-0.8, 1.7, 1>, 0.5 pigment { Paint } finish { ambient 0 brilliance 1 } }
sphere { <0.8, 1.7, 1>, 0.5 pigment { Paint } finish { ambient 0 brilliance 3 } }
sphere { <2.4, 1.7, 1>, 0.5 pigment { Paint } finish { ambient 0 brilliance 8 } }
