// vturbulence(Lambda, Omega, Octaves, <P>) against values printed by POV-Ray 3.7.
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#macro Near(A, B) (vlength(A - B) < 1e-9) #end
Check(Near(vturbulence(2, 0.5, 6, <0.3, 0.2, 0.1>),
  <-0.426615879895319, -0.193939078414595, -0.365478992592628>), "default shape")
Check(Near(vturbulence(2.5, 0.7, 3, <-12.25, 4.5, 33.125>),
  <-0.023623161615321, -0.442093765816973, 0.261401468003686>), "lambda 2.5, omega 0.7, 3 octaves")
Check(Near(vturbulence(2, 0.5, 1, <1.5, -2.75, 0.5>),
  <0.517789672656250, -0.157890910156250, 0.055159061328125>), "one octave is the vector noise")
Check(Near(vturbulence(2, 0.5, 0, <1.5, -2.75, 0.5>),
  vturbulence(2, 0.5, 1, <1.5, -2.75, 0.5>)), "fewer than one octave counts as one")
Check(Near(vturbulence(3, 0.65, 25, <0.7, 0.1, -0.4>),
  <-0.188368784003468, 0.049436244240888, 0.268510688845976>), "more than ten octaves count as ten")
