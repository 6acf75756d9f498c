// Media photons: a narrow spotlight beam enters a box of scattering media (a photon
// target, so it blocks the light's direct shadow rays) and is reflected by a mirror
// inside it; the beams are drawn by the photons deposited along their paths
// (`photons { media 100, 2 }`), gathered by the media samples of the camera rays.
// The beams' brightness matches; their edges differ (5.7% of pixels over 24/255, block
// diff 5.2/255): POV-Ray's automatic media gather radius is not known exactly.
// tolerance: 0.07
#version 3.7;
global_settings { assumed_gamma 1.0
  photons { count 20000 media 100, 2 } }
camera { location <0, 12, 0> look_at 0 right x * 4 / 3 angle 40 }
light_source { <0, 12, 0>, 0.3 photons { refraction off reflection off } media_interaction off }
light_source { <-100, 0.5, 0>, rgb <1.2, 1, 1.5>
  spotlight radius 0.4 falloff 0.5 point_at <0, 0.5, 0>
  photons { refraction on reflection on } }
box { <-20, -1, -20>, <20, 0, 20> pigment { checker rgb 0.8 rgb <0.2, 0, 0.4> } }
box { <-4, -0.1, -3>, <4, 1, 3> hollow pigment { rgbf 1 }
  interior { media { scattering { 1, 1 extinction 0 } samples 4 } }
  photons { target } }
box { <-0.1, -0.1, -1>, <0, 1, 1> rotate y * 45 translate <1, 0, 0>
  pigment { rgb <0.3, 1, 0.3> } finish { ambient 0 diffuse 0 reflection rgb <0.3, 1, 0.3> } }
