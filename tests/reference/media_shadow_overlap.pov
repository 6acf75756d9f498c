// Shadow rays from media through overlapping containers: each container dims the light
// over the stretch the ray is inside it, whatever else it enters or leaves on the way
// (left: the shadow ray of the front box's media enters the back box before it leaves the
// front one), and both of two containers whose faces coincide dim it (right).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> direction z right x * 4 up y * 3 }
background { rgb 0 }
light_source { <0, 200, 1000>, 1 }
#declare Front = media { samples 4 aa_threshold 0.1 aa_level 3 scattering { 1, 0.2 } }
#declare Back = media { samples 2 scattering { 1, <0.05, 0.1, 0.2> * 2 } }
box { <-2, -1, 0>, <-0.1, 0.5, 4> hollow pigment { rgbf 1 } interior { media { Front } } }
box { <-2, -1, 2>, <-0.1, 1, 6> hollow pigment { rgbf 1 } interior { media { Back } } }
box { <0.1, -1, 0>, <2, 1, 4> hollow pigment { rgbf 1 } interior { media { Front } } }
box { <0.1, -1, 2>, <2, 1, 6> hollow pigment { rgbf 1 } interior { media { Back } } }
