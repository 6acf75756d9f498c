#version 3.7;
global_settings { photons { gather 20, 100 } }
