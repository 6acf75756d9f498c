// Prints the animation identifiers; tests/integration/povray_cli.rs compares durer's lines
// with the ones povray 3.7 printed for the same options.
#debug concat("clock=", str(clock, 0, 6), " delta=", str(clock_delta, 0, 6),
  " on=", str(clock_on, 0, 0), " frame=", str(frame_number, 0, 0),
  " if=", str(initial_frame, 0, 0), " ff=", str(final_frame, 0, 0),
  " ic=", str(initial_clock, 0, 4), " fc=", str(final_clock, 0, 4), "\n")
camera { location -5*z look_at 0 }
light_source { <10, 20, -30> rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }
