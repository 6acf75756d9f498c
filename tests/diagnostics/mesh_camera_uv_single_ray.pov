// error: 5:24 2 rays per pixel
// error-text: exactly 1 ray per pixel

#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> uv_vectors <0,0>, <1,0>, <0,1> } }
camera { mesh_camera { 2 3 mesh { M } } }
