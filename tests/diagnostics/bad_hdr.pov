#version 3.7;
height_field { hdr "bad.hdr" }
