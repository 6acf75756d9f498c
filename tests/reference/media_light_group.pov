// media_light_group: light groups rule scattering media as they rule surfaces. The negative
// light of the left group darkens only its box, not the media sphere around the camera; the
// right sphere's media sit in a group without global lights, so only the group's own light
// (from above) lights them, not the scene light (from below)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at 0 }
light_source { <0, -6, -2> rgb 1.5 }
sphere { 0, 20 hollow
  pigment { rgbt 1 }
  interior { media { scattering { 1, 0.006 } method 3 } }
}
light_group {
  box { -0.8, 0.8 rotate <20, 30, 0> pigment { rgb 1 } }
  light_source { <-1, 0, -4> rgb -2 shadowless }
  global_lights on
  translate -x * 2
}
light_group {
  sphere { 0, 1.5 hollow
    pigment { rgbt 1 }
    interior { media { scattering { 1, 0.15 } method 3 } }
  }
  light_source { <0, 5, 0> rgb 2 }
  translate x * 2
}
