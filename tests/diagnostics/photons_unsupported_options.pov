// warning: 5:43 area light photons
// warning: 6:76 `split_union off`

global_settings { photons { spacing 0.1 } }
light_source { <0, 5, -5> rgb 1 photons { area_light } }
union { sphere { 0, 1 } sphere { 1, 1 } pigment { rgb 1 } photons { target split_union off } }
