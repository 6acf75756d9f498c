// warning: 6:40 radiosity sample files are not read or written; `load_file` is ignored
// warning: 6:62 radiosity sample files are not read or written; `save_file` is ignored

// povray reuses a saved cache; durer computes the samples afresh, the same picture.
#version 3.7;
global_settings { radiosity { count 20 load_file "scene.rad" save_file "scene.rad" } }
sphere { 0, 1 pigment { rgb 1 } }
