// error: 5:44 pretrace block size 1.5 is out of range
// error-text: above 0 and at most 1

#version 3.7;
global_settings { radiosity { pretrace_end 1.5 } }
