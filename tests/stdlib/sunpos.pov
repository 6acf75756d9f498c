// Places the sun with sunpos.inc for several dates, times and places (including clocks that
// roll over midnight either way and a longitude far from its time zone) and writes what
// SunPos declares and returns, one `name values..` line each, to probe.txt;
// tests/integration/includes.rs runs it with durer's embedded sunpos.inc and compares the
// result with POV-Ray's output.
#version 3.7;
#include "sunpos.inc"
#fopen Out "probe.txt" write
#macro Put(Name, Value)
  #write (Out, Name, " ", vstr(3, <0, 0, 0> + (Value), " ", 0, 9), "\n")
#end
#macro Probe(Name, Year, Month, Day, Hour, Minute, Lstm, Lat, Long)
  #local Returned = SunPos(Year, Month, Day, Hour, Minute, Lstm, Lat, Long);
  Put(concat(Name, " Al Az"), <Al, Az, 0>)
  Put(concat(Name, " SolarPosition"), SolarPosition / 1e6)
  Put(concat(Name, " returned"), Returned / 1e6)
#end
Probe("Greenwich noon", 2000, 6, 21, 12, 0, 0, 51.48, 0)
Probe("Amsterdam morning", 2004, 3, 15, 8, 30, 15, 52.37, 4.9)
Probe("Sydney evening", 1995, 12, 24, 19, 45, 150, -33.87, 151.2)
Probe("Honolulu before midnight UTC", 2010, 9, 1, 22, 10, -150, 21.3, -157.86)
Probe("Tokyo after midnight UTC", 2021, 1, 31, 3, 5, 135, 35.68, 139.69)
Probe("far from meridian", 1987, 7, 4, 16, 20, 0, 40.0, 60.0)
Probe("leap day", 2024, 2, 29, 0, 0, 60, 55.75, 37.62)
#fclose Out
