// camera_mesh_stereo: mesh_camera distribution 2 (side-by-side meshes, a stereo pair)
// and distribution-independent `location` z and negative `direction` z (rays against
// the face normals)
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Columns = image_width / 2;
#declare Pixel = 4 / Columns;
#declare Faces = mesh {
  #for (Row, 0, image_height - 1)
    #for (Column, 0, Columns - 1)
      #local Centre = <(Column + 0.5) * Pixel - 2, 1.5 * 4 / 3 - (Row + 0.5) * Pixel * 2 / 3, 0>;
      // Clockwise seen from -z: the normal points to -z, the direction flips it back.
      triangle { Centre + <0, Pixel / 3, 0>, Centre + <-Pixel / 3, -Pixel / 4, 0>, Centre + <Pixel / 3, -Pixel / 4, 0> }
    #end
  #end
}
camera {
  mesh_camera { 1 2
    mesh { Faces rotate 25*x translate <-0.3, 3, -5> }
    mesh { Faces rotate 25*x translate <0.3, 3, -5> }
  }
  location <0, 0, 0.5>
  direction <0, 0, -1>
}
light_source { <-5, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.3 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.6 } }
box { <-1.8, 0, -0.5>, <-1, 0.8, 0.3> pigment { rgb <0.2, 0.5, 0.9> } }
