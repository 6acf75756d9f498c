// A `global_settings { noise_generator }` written after the patterns applies to every
// pattern without its own generator (POV-Ray reads the scene's last setting when it
// evaluates them; a later `global_settings` without one changes nothing). The right-hand
// pattern names its own generator and keeps it.
#version 3.7;
global_settings { assumed_gamma 1 noise_generator 3 }
camera { orthographic location <0, 0, -10> look_at 0 right x * 4 up y * 3 }
#declare Map = color_map { [0 rgb <0.1, 0, 0.3>] [0.5 rgb <1, 0.6, 0.1>] [1 rgb 1] }
plane { z, 0
  texture {
    pigment { bozo scale 0.3 color_map { Map } }
    finish { ambient 1 diffuse 0 }
  }
  clipped_by { box { <-2, 0, -1>, <0, 1.5, 1> } }
}
plane { z, 0
  texture {
    pigment { granite scale 2 warp { turbulence 0.4 } color_map { Map } }
    finish { ambient 1 diffuse 0 }
  }
  clipped_by { box { <-2, -1.5, -1>, <0, 0, 1> } }
}
plane { z, 0
  texture {
    pigment { bozo scale 0.3 noise_generator 2 color_map { Map } }
    finish { ambient 1 diffuse 0 }
  }
  clipped_by { box { <0, 0, -1>, <2, 1.5, 1> } }
}
plane { z, 0
  texture {
    pigment { rgb <0.3, 0.5, 0.8> }
    normal { wrinkles 1 scale 0.4 turbulence 0.3 }
    finish { ambient 0.2 diffuse 0.8 }
  }
  clipped_by { box { <0, -1.5, -1>, <2, 0, 1> } }
}
light_source { <-5, 5, -10> rgb 1 }
global_settings { noise_generator 1 }
global_settings { max_trace_level 6 }
