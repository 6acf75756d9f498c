// Atmospheric scattering media lit by two spotlights (one dimmed by the media on its way,
// one coloured), a shadowless light that does not light the media, and a sphere casting
// shadows into the beams; Mie haze scattering inside a box.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -12> look_at <0, 3, 0> angle 60 }
media { scattering { 1, rgb 0.04 } samples 6 }
light_source { <0, 12, 0> rgb 0.5 media_interaction off shadowless }
light_source { <-3, 10, -2> rgb <1, 0.4, 0.3> * 2
  spotlight point_at <0, 3, 0> radius 10 falloff 16 tightness 1 media_attenuation on }
light_source { <4, 10, 0> rgb <0.3, 0.6, 1> * 2
  spotlight point_at <1, 0, 0> radius 6 falloff 12 }
box { <-10, 0, -15>, <10, 12, 10> pigment { rgb 1 } finish { ambient 0.1 diffuse 0.6 } hollow }
sphere { <0, 4, 0>, 1 pigment { rgb 1 } finish { ambient 0.2 diffuse 0.7 } }
box { <3, 0, 3>, <6, 3, 6>
  pigment { rgbt 1 }
  hollow
  interior { media { scattering { 2, rgb 0.3 } } }
}
