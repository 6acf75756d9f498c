// Object media: a hollow sphere of emitting and absorbing media whose density is a
// spherical pattern with a colour map (method 3 subdivides at the colour steps), and a
// box of constant absorption, in front of a checkered wall.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -6> look_at 0 angle 50 }
background { rgb 0.1 }
light_source { <-5, 8, -10> rgb 1 }
plane { -z, -3 pigment { checker rgb 1, rgb <0.2, 0.3, 0.6> } finish { ambient 0.3 } }
sphere { 0, 1
  pigment { rgbt 1 }
  hollow
  interior {
    media {
      emission 1.2
      absorption <0.2, 0.8, 1.4>
      density {
        spherical
        color_map { [0 rgb 0] [0.4 rgb <1, 0.3, 0>] [0.7 rgb <1, 1, 0.2>] [1 rgb 1] }
      }
    }
  }
  translate <-1.2, 0, 0>
}
box { -0.8, 0.8
  pigment { rgbf <1, 1, 1, 1> }
  hollow
  interior { media { absorption 0.7 samples 4 } }
  rotate <20, 30, 0>
  translate <1.3, 0, 0>
}
