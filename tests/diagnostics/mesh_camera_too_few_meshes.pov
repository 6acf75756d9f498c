// error: 4:24 distribution 0 needs a mesh for each of the 2 rays per pixel, found 1 meshes

#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
camera { mesh_camera { 2, 0 mesh { M } } }
