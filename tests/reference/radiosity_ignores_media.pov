// radiosity_ignores_media: radiosity's gathering rays do not see media unless the radiosity
// block says `media on` (POV-Ray's default is off): the bright emitting shell around the scene
// lights it only through the camera's view of it, not through radiosity.
#version 3.7;
global_settings { radiosity { count 40 error_bound 0.8 nearest_count 5 recursion_limit 1 } }
#default { texture { finish { ambient 0 diffuse 1 } } }
camera { location <0, 1.5, -4> look_at <0, 0.8, 0> }
light_source { <3, 5, -4> rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <0, 0.8, 0>, 0.8 pigment { rgb <1, 0.4, 0.2> } }
difference {
  sphere { 0, 100 }
  sphere { 0, 99 }
  pigment { rgbt 1 }
  finish { ambient 0 diffuse 0 }
  interior { media { emission 0.05 } }
  hollow no_shadow
}
