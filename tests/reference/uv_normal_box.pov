// uv_mapping in a texture applies to its normal too: on boxes the bumps follow the faces'
// unfolded uv layout, the object's rotation and scale leave them be, the normal's own
// transformations apply.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 0, 0> angle 45 }
light_source { <-4, 7, -5> rgb 1 }
box { -1, 1
  texture {
    uv_mapping
    pigment { rgb <0.9, 0.8, 0.5> }
    normal { gradient x 2 scale 0.05 }
  }
  rotate <20, 35, 0> scale 0.8 translate <-1.3, 0, 0>
}
box { -1, 1
  texture {
    pigment { rgb <0.6, 1, 0.6> }
    normal { uv_mapping wrinkles 1 scale <0.05, 0.1, 1> rotate z * 20 }
    finish { phong 0.5 }
  }
  rotate <-30, -25, 0> scale 0.8 translate <1.3, 0, 0>
}
plane { y, -1.2 pigment { rgb 0.6 } }
