#version 3.7;
global_settings { radiosity { pretrace_end 1.5 } }
