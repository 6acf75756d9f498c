// camera_mesh_max_distance: mesh_camera distribution 1 (meshes summed, one ray per pixel)
// with max_distance: objects farther than 7.5 from a ray's origin are not seen (the
// background shows), while shadows and reflections still reach beyond
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Pixel = 4 / image_width;
#macro Half(First, Last)
  mesh {
    #for (Row, First, Last)
      #for (Column, 0, image_width - 1)
        #local Centre = <(Column + 0.5) * Pixel - 2, 1.5 - (Row + 0.5) * Pixel, 0>;
        triangle { Centre + <0, Pixel / 3, 0>, Centre + <Pixel / 3, -Pixel / 4, 0>, Centre + <-Pixel / 3, -Pixel / 4, 0> }
      #end
    #end
  }
#end
#declare Top = Half(0, image_height / 2 - 1)
#declare Bottom = Half(image_height / 2, image_height - 1)
camera {
  mesh_camera { 1 1 7.5
    mesh { Top rotate 20*x translate <0, 3, -6> }
    mesh { Bottom rotate 20*x translate <0, 3, -6> }
  }
  location <0, 0, -0.5>
}
background { rgb <0.2, 0.3, 0.5> }
light_source { <-5, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.3 } finish { reflection 0.2 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.6 } }
box { <-1.8, 0, -0.5>, <-1, 0.8, 0.3> pigment { rgb <0.2, 0.5, 0.9> } }
sphere { <1.5, 0.6, 3>, 0.6 pigment { rgb <0.3, 0.9, 0.3> } }
