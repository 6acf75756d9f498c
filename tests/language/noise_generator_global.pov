// Patterns without their own `noise_generator` follow the scene's global one as it stands
// when they are evaluated: functions called while parsing see each `global_settings` as it
// comes (a `global_settings` without `noise_generator` changes nothing); a pattern's own
// generator stays. Values printed by POV-Ray 3.7.
#version 3.7;
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#macro Near(A, B) (abs(A - B) < 1e-6) #end
#declare Bozo = function { pattern { bozo } }
#declare BozoPigment = function { pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } } }
#declare Stirred = function { pattern { marble turbulence 0.5 } }
#declare OwnGenerator = function { pattern { bozo noise_generator 3 } }
#declare P = <0.3, 0.2, 0.1>;
Check(Near(Bozo(P.x, P.y, P.z), 0.373438962488), "generator 2 by default")
Check(Near(BozoPigment(P.x, P.y, P.z).red, 0.373438954353), "pigment function, generator 2")
Check(Near(Stirred(P.x, P.y, P.z), 0.772420173885), "turbulence, generator 2")
global_settings { noise_generator 1 }
Check(Near(Bozo(P.x, P.y, P.z), 0.209924647632), "a later generator 1 applies")
Check(Near(BozoPigment(P.x, P.y, P.z).red, 0.209924653172), "pigment function, generator 1")
Check(Near(Stirred(P.x, P.y, P.z), 0.842240879895), "turbulence, generator 1")
Check(Near(OwnGenerator(P.x, P.y, P.z), 0.578735912427), "own generator 3 stays")
global_settings { noise_generator 3 }
global_settings { max_trace_level 3 }
Check(Near(Bozo(P.x, P.y, P.z), 0.578735912427), "generator 3, kept by a later block without one")
Check(Near(Stirred(P.x, P.y, P.z), 0.172238565535), "turbulence, generator 3")
global_settings { noise_generator 2 }
// functions.inc's f_noise3d (internal 76) and the functions built on it follow the scene's
// generator too, also in a function declared before the setting.
#include "functions.inc"
#declare Noise = function { f_noise3d(x, y, z) }
Check(Near(Noise(0.3, 1.7, 2.2), 0.351489497865), "f_noise3d, generator 2")
global_settings { noise_generator 1 }
Check(Near(Noise(0.3, 1.7, 2.2), 0.165116637341), "f_noise3d, a later generator 1")
Check(Near(f_snoise3d(0.3, 1.7, 2.2), -0.669766725319), "f_snoise3d, generator 1")
Check(Near(f_bozo(0.3, 1.7, 2.2), 0.165116637341), "f_bozo, generator 1")
global_settings { noise_generator 3 }
Check(Near(Noise(0.3, 1.7, 2.2), 0.356115400452), "f_noise3d, generator 3")
global_settings { noise_generator 2 }
