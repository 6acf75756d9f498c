// camera_mesh: mesh_camera distribution 0 with two rays per pixel (two meshes, the second
// shifted by half a pixel, so their colours average), faces looking along +z
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Pixel = 4 / image_width;
#declare Faces = mesh {
  #for (Row, 0, image_height - 1)
    #for (Column, 0, image_width - 1)
      #local Centre = <(Column + 0.5) * Pixel - 2, 1.5 - (Row + 0.5) * Pixel, 0>;
      triangle { Centre + <0, Pixel / 3, 0>, Centre + <Pixel / 3, -Pixel / 4, 0>, Centre + <-Pixel / 3, -Pixel / 4, 0> }
    #end
  #end
}
camera {
  mesh_camera { 2 0
    mesh { Faces rotate -20*x translate <0, 2, -6> }
    mesh { Faces translate <Pixel / 2, 0, 0> rotate -20*x translate <0, 2, -6> }
  }
  location <0, 0, -0.5>
}
light_source { <-5, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.3 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.6 } }
box { <-1.8, 0, -0.5>, <-1, 0.8, 0.3> pigment { rgb <0.2, 0.5, 0.9> } }
