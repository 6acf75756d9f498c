// error: 4:37 the photon spacing -0.1 must be positive

#version 3.7;
global_settings { photons { spacing -0.1 } }
