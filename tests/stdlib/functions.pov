// Calls the functions of functions.inc durer can evaluate and writes one `name value` line
// each to probe.txt, then `name defined` for every name the file declares;
// tests/integration/includes.rs runs it with durer's embedded functions.inc and compares the
// result with POV-Ray's output. (Pattern and pigment functions, eval_pigment and the internal
// functions durer lacks cannot be called from the scene language yet.)
// f_torus2 stays within [-10, 10] here: POV-Ray clamps it there and durer does not yet.
#version 3.7;
#include "functions.inc"
#fopen Out "probe.txt" write
#macro Put(Name, Value)
  #write (Out, Name, " ", str(Value, 0, 9), "\n")
#end

#declare Points = array[4] {<0.31, 0.27, 0.13>, <-1.5, 2, 0.75>, <0, 0, 0>, <2.2, -0.4, -3>}
#for (I, 0, 3)
  #declare P = Points[I];
  #declare S = concat(" ", str(I, 0, 0));
  Put(concat("f_ellipsoid", S), f_ellipsoid(P.x, P.y, P.z, 1, 2, 0.5))
  Put(concat("f_paraboloid", S), f_paraboloid(P.x, P.y, P.z, 0.7))
  Put(concat("f_ph", S), f_ph(P.x + 0.1, P.y, P.z))
  Put(concat("f_r", S), f_r(P.x, P.y, P.z))
  Put(concat("f_rounded_box", S), f_rounded_box(P.x, P.y, P.z, 0.2, 1, 1.5, 0.5))
  Put(concat("f_sphere", S), f_sphere(P.x, P.y, P.z, 1.2))
  Put(concat("f_superellipsoid", S), f_superellipsoid(P.x, P.y, P.z, 0.5, 0.8))
  Put(concat("f_th", S), f_th(P.x, P.y, P.z))
  Put(concat("f_torus", S), f_torus(P.x, P.y, P.z, 1, 0.25))
  Put(concat("f_torus2", S), f_torus2(P.x, P.y, P.z, 0.05, 1, 0.25))
  Put(concat("f_noise3d", S), f_noise3d(P.x, P.y, P.z))
  Put(concat("f_snoise3d", S), f_snoise3d(P.x, P.y, P.z))
  #for (Generator, 1, 3)
    Put(concat("f_noise_generator", S, " ", str(Generator, 0, 0)),
      f_noise_generator(P.x, P.y, P.z, Generator))
  #end
  Put(concat("f_bozo", S), f_bozo(P.x, P.y, P.z))
  Put(concat("f_bumps", S), f_bumps(P.x, P.y, P.z))
  Put(concat("f_dents", S), f_dents(P.x, P.y, P.z))
  Put(concat("f_spotted", S), f_spotted(P.x, P.y, P.z))
  Put(concat("f_sine_wave", S), f_sine_wave(P.x, P.y, P.z))
  Put(concat("f_scallop_wave", S), f_scallop_wave(P.x, -P.y, P.z))
#end

#ifdef (f_algbr_cyl1) #write (Out, "f_algbr_cyl1 defined\n") #end
#ifdef (f_algbr_cyl2) #write (Out, "f_algbr_cyl2 defined\n") #end
#ifdef (f_algbr_cyl3) #write (Out, "f_algbr_cyl3 defined\n") #end
#ifdef (f_algbr_cyl4) #write (Out, "f_algbr_cyl4 defined\n") #end
#ifdef (f_bicorn) #write (Out, "f_bicorn defined\n") #end
#ifdef (f_bifolia) #write (Out, "f_bifolia defined\n") #end
#ifdef (f_blob) #write (Out, "f_blob defined\n") #end
#ifdef (f_blob2) #write (Out, "f_blob2 defined\n") #end
#ifdef (f_boy_surface) #write (Out, "f_boy_surface defined\n") #end
#ifdef (f_comma) #write (Out, "f_comma defined\n") #end
#ifdef (f_cross_ellipsoids) #write (Out, "f_cross_ellipsoids defined\n") #end
#ifdef (f_crossed_trough) #write (Out, "f_crossed_trough defined\n") #end
#ifdef (f_cubic_saddle) #write (Out, "f_cubic_saddle defined\n") #end
#ifdef (f_cushion) #write (Out, "f_cushion defined\n") #end
#ifdef (f_devils_curve) #write (Out, "f_devils_curve defined\n") #end
#ifdef (f_devils_curve_2d) #write (Out, "f_devils_curve_2d defined\n") #end
#ifdef (f_dupin_cyclid) #write (Out, "f_dupin_cyclid defined\n") #end
#ifdef (f_ellipsoid) #write (Out, "f_ellipsoid defined\n") #end
#ifdef (f_enneper) #write (Out, "f_enneper defined\n") #end
#ifdef (f_flange_cover) #write (Out, "f_flange_cover defined\n") #end
#ifdef (f_folium_surface) #write (Out, "f_folium_surface defined\n") #end
#ifdef (f_folium_surface_2d) #write (Out, "f_folium_surface_2d defined\n") #end
#ifdef (f_glob) #write (Out, "f_glob defined\n") #end
#ifdef (f_heart) #write (Out, "f_heart defined\n") #end
#ifdef (f_helical_torus) #write (Out, "f_helical_torus defined\n") #end
#ifdef (f_helix1) #write (Out, "f_helix1 defined\n") #end
#ifdef (f_helix2) #write (Out, "f_helix2 defined\n") #end
#ifdef (f_hex_x) #write (Out, "f_hex_x defined\n") #end
#ifdef (f_hex_y) #write (Out, "f_hex_y defined\n") #end
#ifdef (f_hetero_mf) #write (Out, "f_hetero_mf defined\n") #end
#ifdef (f_hunt_surface) #write (Out, "f_hunt_surface defined\n") #end
#ifdef (f_hyperbolic_torus) #write (Out, "f_hyperbolic_torus defined\n") #end
#ifdef (f_isect_ellipsoids) #write (Out, "f_isect_ellipsoids defined\n") #end
#ifdef (f_kampyle_of_eudoxus) #write (Out, "f_kampyle_of_eudoxus defined\n") #end
#ifdef (f_kampyle_of_eudoxus_2d) #write (Out, "f_kampyle_of_eudoxus_2d defined\n") #end
#ifdef (f_klein_bottle) #write (Out, "f_klein_bottle defined\n") #end
#ifdef (f_kummer_surface_v1) #write (Out, "f_kummer_surface_v1 defined\n") #end
#ifdef (f_kummer_surface_v2) #write (Out, "f_kummer_surface_v2 defined\n") #end
#ifdef (f_lemniscate_of_gerono) #write (Out, "f_lemniscate_of_gerono defined\n") #end
#ifdef (f_lemniscate_of_gerono_2d) #write (Out, "f_lemniscate_of_gerono_2d defined\n") #end
#ifdef (f_mesh1) #write (Out, "f_mesh1 defined\n") #end
#ifdef (f_mitre) #write (Out, "f_mitre defined\n") #end
#ifdef (f_nodal_cubic) #write (Out, "f_nodal_cubic defined\n") #end
#ifdef (f_odd) #write (Out, "f_odd defined\n") #end
#ifdef (f_ovals_of_cassini) #write (Out, "f_ovals_of_cassini defined\n") #end
#ifdef (f_paraboloid) #write (Out, "f_paraboloid defined\n") #end
#ifdef (f_parabolic_torus) #write (Out, "f_parabolic_torus defined\n") #end
#ifdef (f_ph) #write (Out, "f_ph defined\n") #end
#ifdef (f_pillow) #write (Out, "f_pillow defined\n") #end
#ifdef (f_piriform) #write (Out, "f_piriform defined\n") #end
#ifdef (f_piriform_2d) #write (Out, "f_piriform_2d defined\n") #end
#ifdef (f_poly4) #write (Out, "f_poly4 defined\n") #end
#ifdef (f_polytubes) #write (Out, "f_polytubes defined\n") #end
#ifdef (f_quantum) #write (Out, "f_quantum defined\n") #end
#ifdef (f_quartic_paraboloid) #write (Out, "f_quartic_paraboloid defined\n") #end
#ifdef (f_quartic_saddle) #write (Out, "f_quartic_saddle defined\n") #end
#ifdef (f_quartic_cylinder) #write (Out, "f_quartic_cylinder defined\n") #end
#ifdef (f_r) #write (Out, "f_r defined\n") #end
#ifdef (f_ridge) #write (Out, "f_ridge defined\n") #end
#ifdef (f_ridged_mf) #write (Out, "f_ridged_mf defined\n") #end
#ifdef (f_rounded_box) #write (Out, "f_rounded_box defined\n") #end
#ifdef (f_sphere) #write (Out, "f_sphere defined\n") #end
#ifdef (f_spikes) #write (Out, "f_spikes defined\n") #end
#ifdef (f_spikes_2d) #write (Out, "f_spikes_2d defined\n") #end
#ifdef (f_spiral) #write (Out, "f_spiral defined\n") #end
#ifdef (f_steiners_roman) #write (Out, "f_steiners_roman defined\n") #end
#ifdef (f_strophoid) #write (Out, "f_strophoid defined\n") #end
#ifdef (f_strophoid_2d) #write (Out, "f_strophoid_2d defined\n") #end
#ifdef (f_superellipsoid) #write (Out, "f_superellipsoid defined\n") #end
#ifdef (f_th) #write (Out, "f_th defined\n") #end
#ifdef (f_torus) #write (Out, "f_torus defined\n") #end
#ifdef (f_torus2) #write (Out, "f_torus2 defined\n") #end
#ifdef (f_torus_gumdrop) #write (Out, "f_torus_gumdrop defined\n") #end
#ifdef (f_umbrella) #write (Out, "f_umbrella defined\n") #end
#ifdef (f_witch_of_agnesi) #write (Out, "f_witch_of_agnesi defined\n") #end
#ifdef (f_witch_of_agnesi_2d) #write (Out, "f_witch_of_agnesi_2d defined\n") #end
#ifdef (f_noise3d) #write (Out, "f_noise3d defined\n") #end
#ifdef (f_snoise3d) #write (Out, "f_snoise3d defined\n") #end
#ifdef (f_noise_generator) #write (Out, "f_noise_generator defined\n") #end
#ifdef (f_agate) #write (Out, "f_agate defined\n") #end
#ifdef (f_boxed) #write (Out, "f_boxed defined\n") #end
#ifdef (f_bozo) #write (Out, "f_bozo defined\n") #end
#ifdef (f_brick) #write (Out, "f_brick defined\n") #end
#ifdef (f_bumps) #write (Out, "f_bumps defined\n") #end
#ifdef (f_checker) #write (Out, "f_checker defined\n") #end
#ifdef (f_crackle) #write (Out, "f_crackle defined\n") #end
#ifdef (f_cylindrical) #write (Out, "f_cylindrical defined\n") #end
#ifdef (f_dents) #write (Out, "f_dents defined\n") #end
#ifdef (f_gradientX) #write (Out, "f_gradientX defined\n") #end
#ifdef (f_gradientY) #write (Out, "f_gradientY defined\n") #end
#ifdef (f_gradientZ) #write (Out, "f_gradientZ defined\n") #end
#ifdef (f_granite) #write (Out, "f_granite defined\n") #end
#ifdef (f_hexagon) #write (Out, "f_hexagon defined\n") #end
#ifdef (f_leopard) #write (Out, "f_leopard defined\n") #end
#ifdef (f_mandel) #write (Out, "f_mandel defined\n") #end
#ifdef (f_marble) #write (Out, "f_marble defined\n") #end
#ifdef (f_onion) #write (Out, "f_onion defined\n") #end
#ifdef (f_planar) #write (Out, "f_planar defined\n") #end
#ifdef (f_radial) #write (Out, "f_radial defined\n") #end
#ifdef (f_ripples) #write (Out, "f_ripples defined\n") #end
#ifdef (f_spherical) #write (Out, "f_spherical defined\n") #end
#ifdef (f_spiral1) #write (Out, "f_spiral1 defined\n") #end
#ifdef (f_spiral2) #write (Out, "f_spiral2 defined\n") #end
#ifdef (f_spotted) #write (Out, "f_spotted defined\n") #end
#ifdef (f_waves) #write (Out, "f_waves defined\n") #end
#ifdef (f_wood) #write (Out, "f_wood defined\n") #end
#ifdef (f_wrinkles) #write (Out, "f_wrinkles defined\n") #end
#ifdef (f_sine_wave) #write (Out, "f_sine_wave defined\n") #end
#ifdef (f_scallop_wave) #write (Out, "f_scallop_wave defined\n") #end
#ifdef (eval_pigment) #write (Out, "eval_pigment defined\n") #end
#fclose Out
