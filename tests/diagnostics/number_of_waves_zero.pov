#version 3.7;
global_settings { number_of_waves 0 }
