// Radiosity, media and subsurface settings evaluate: read with no effect where durer does not
// use them (object `radiosity { importance }`, radiosity `adc_bailout`, media `confidence`,
// `variance`, `ratio`, subsurface `anisotropy` and `radiosity`).
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { count 20, 400 adc_bailout 0.005 media on normal on always_sample off }
  mm_per_unit 25.4
  subsurface { samples 400, 40 radiosity off }
}
sphere { 0, 1 pigment { rgb 1 } radiosity { importance 0.25 } }
#declare Thing = box { -1, 1 radiosity { importance 1 } no_radiosity }
object { Thing pigment { rgb 0.5 } finish { subsurface { translucency <0.5, 0.4, 0.3> anisotropy 0.2 } } }
sphere { 0, 1 finish { subsurface { translucency 2 } subsurface { } } }
box { -1, 1 pigment { rgbt 1 } hollow
  interior { media { method 2 samples 5 confidence 0.8 variance 1/64 ratio 0.8 emission 0.1 } }
}
