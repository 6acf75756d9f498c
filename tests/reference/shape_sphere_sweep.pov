// shape_sphere_sweep: linear_spline with growing radii, b_spline and cubic_spline sweeps.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.7, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
sphere_sweep { linear_spline 4, <-2.8, 0.3, 0>, 0.15, <-2.2, 1.4, 0.3>, 0.3, <-1.6, 0.4, -0.2>, 0.2, <-1.2, 1.6, 0>, 0.4
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
sphere_sweep { b_spline 6, <-0.9, 0.3, 0>, 0.2, <-0.6, 1.8, 0>, 0.2, <0, 0.2, -0.5>, 0.3, <0.4, 1.6, 0>, 0.15, <0.8, 0.3, 0.4>, 0.25, <1, 1, 0>, 0.2
  tolerance 0.001
  pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.5 } }
sphere_sweep { cubic_spline 5, <1.2, 0.5, 0>, 0.1, <1.4, 0.4, 0>, 0.2, <2, 1.6, 0.3>, 0.3, <2.8, 0.4, -0.2>, 0.15, <3, 1.5, 0>, 0.2
  pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.5 } }
