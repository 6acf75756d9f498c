// error: 5:7 cannot pass undefined identifier `Nothing` to a macro

// A macro argument naming nothing.
#macro SetTo(P) #local P = 5; #end
SetTo(Nothing)
