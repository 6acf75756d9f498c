// error: 4:39 `smooth` needs mesh camera distribution 3

#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
camera { mesh_camera { 1 0 mesh { M } smooth } }
