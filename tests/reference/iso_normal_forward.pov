// iso_normal_forward: isosurface normals are forward differences over one `accuracy` step,
// as POV-Ray takes them. A coarse accuracy on fine ripples makes the difference visible
// (central differences shade the ripples' slopes differently)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -4> look_at <0, 0, 0> angle 40 }
light_source { <-3, 5, -2> rgb 1.2 }
isosurface {
  function { y - 0.012 * sin(x * 70) * cos(z * 50) }
  contained_by { box { <-2, -0.5, -2>, <2, 0.5, 2> } }
  accuracy 0.012
  max_gradient 3
  pigment { rgb <0.9, 0.7, 0.4> }
  finish { specular 0.4 }
}
