// warning: 4:1 the uv rectangle of this parametric has no area: it shows nothing

// povray renders nothing for it, without a word (a scene's `<0, 0>, <2*pi, pi*clock>` at clock 0).
parametric { function { sin(u)*cos(v) } function { sin(u)*sin(v) } function { cos(u) } <0,0>, <2*pi, 0> contained_by { sphere { 0, 2 } } pigment { rgb <1,0,0> } }
