// error: 4:32 photon spacing multiplier 0 must be positive

#version 3.7;
sphere { 0, 1 photons { target 0 } }
