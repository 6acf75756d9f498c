// A macro argument naming nothing.
#macro SetTo(P) #local P = 5; #end
SetTo(Nothing)
