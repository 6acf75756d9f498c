// warning: 5:35 number_of_waves
// warning-text: must be greater than 0; 1 is used

#version 3.7;
global_settings { number_of_waves 0 }
