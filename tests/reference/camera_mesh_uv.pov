// camera_mesh_uv: mesh_camera distribution 3 (each pixel's uv coordinates pick the point
// on a uv-mapped mesh its ray starts from) with `smooth` (rays along the interpolated
// corner normals): a bulging grid of smooth triangles, coarser than the image, seen
// through uv coordinates
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Columns = 16;
#declare Rows = 12;
// The corner at grid point (I, J): on a sphere of radius 3 around <0, 0, -3>, looking +z.
#macro Corner(I, J)
  <(I / Columns - 0.5) * 2, (J / Rows - 0.5) * 1.5, 0>
#end
#macro Lens(P) (vnormalize(P + <0, 0, 3>) * 3 - <0, 0, 3>) #end
#macro LensNormal(P) vnormalize(P + <0, 0, 3>) #end
#declare Lens_Mesh = mesh {
  #for (J, 0, Rows - 1)
    #for (I, 0, Columns - 1)
      #local A = Corner(I, J); #local B = Corner(I + 1, J);
      #local C = Corner(I + 1, J + 1); #local D = Corner(I, J + 1);
      // Clockwise seen from -z: the face normals point to +z, like the corner normals.
      smooth_triangle { Lens(A), LensNormal(A), Lens(D), LensNormal(D), Lens(C), LensNormal(C)
        uv_vectors <I / Columns, J / Rows>, <I / Columns, (J + 1) / Rows>, <(I + 1) / Columns, (J + 1) / Rows> }
      smooth_triangle { Lens(A), LensNormal(A), Lens(C), LensNormal(C), Lens(B), LensNormal(B)
        uv_vectors <I / Columns, J / Rows>, <(I + 1) / Columns, (J + 1) / Rows>, <(I + 1) / Columns, J / Rows> }
    #end
  #end
}
camera {
  mesh_camera { 1 3
    mesh { Lens_Mesh rotate 15*x translate <0, 1.6, -5> }
    smooth
  }
  location <0, 0, 0.01>
}
light_source { <-5, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.3 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.6 } }
box { <-1.8, 0, -0.5>, <-1, 0.8, 0.3> pigment { rgb <0.2, 0.5, 0.9> } }
