#version 3.7;
global_settings { radiosity { count 0 } }
