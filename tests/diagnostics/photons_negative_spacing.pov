#version 3.7;
global_settings { photons { spacing -0.1 } }
