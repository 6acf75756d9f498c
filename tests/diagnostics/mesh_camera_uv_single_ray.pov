#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> uv_vectors <0,0>, <1,0>, <0,1> } }
camera { mesh_camera { 2 3 mesh { M } } }
