// error: 5:37 radiosity value 0 is out of range
// error-text: expected a whole number from 1 to

#version 3.7;
global_settings { radiosity { count 0 } }
