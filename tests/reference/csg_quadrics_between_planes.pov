// Intersections of unbounded quadrics and planes (chess pieces as POV-Ray's chess2 builds
// them): a hyperboloid, a cone and a cylinder, each cut to a finite piece only by planes and
// by each other (no bounded child), plus a difference removing a scaled, moved paraboloid.
// durer bounds such pieces by cutting the quadrics to the planes' slab (tracing is unchanged).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -12> look_at <0, 2, 0> angle 45 }
light_source { <-6, 10, -8> rgb 1 }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.5 } }
// x² + z² − y² − 1 < 0 between y = 2.5 and y = 5.5, scaled narrower and moved.
intersection {
  plane { y, 5.5 }
  quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -1 translate 5 * y scale <0.4, 1, 0.4> }
  plane { -y, -2.5 }
  translate <-3, -2.5, 0>
  pigment { rgb <1, 0.3, 0.2> }
}
// A cone x² + z² − y² < 0 between two tilted planes.
intersection {
  quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, 0 }
  plane { y, 3 }
  plane { <0.3, -1, 0>, -0.5 }
  scale 0.8
  pigment { rgb <0.2, 0.8, 0.3> }
}
// A cylinder x² + z² − 1 < 0 cut by two planes, minus a paraboloid x² + z² − y < 0.
difference {
  intersection {
    quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
    plane { y, 3 }
    plane { -y, 0 }
  }
  quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0 scale 0.7 translate 1.5 * y }
  translate 3 * x
  pigment { rgb <0.3, 0.4, 1> }
}
