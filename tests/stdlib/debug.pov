// Exercises every macro of debug.inc and writes the switch and flags it sets, one
// `name value` line each, to probe.txt; tests/integration/includes.rs runs it with durer's
// embedded debug.inc and compares the result with POV-Ray's output.
#version 3.7;
#include "debug.inc"
#fopen Out "probe.txt" write
#write (Out, "DEBUG_MCR ", str(DEBUG_MCR, 0, 0), "\n")
#write (Out, "DEBUG ", str(DEBUG, 0, 0), "\n")
Set_Debug(off)
#write (Out, "DEBUG after Set_Debug(off) ", str(DEBUG, 0, 0), "\n")
Debug_Message("not printed while DEBUG is off\n")
Set_Debug(on)
#write (Out, "DEBUG after Set_Debug(on) ", str(DEBUG, 0, 0), "\n")
Debug_Message("printed while DEBUG is on\n")
#ifdef (View_POV_Include_Stack)
  #write (Out, "View_POV_Include_Stack before Debug_Inc_Stack\n")
#end
Debug_Inc_Stack()
#write (Out, "View_POV_Include_Stack ", str(View_POV_Include_Stack, 0, 0), "\n")
Debug(false, "not printed\n")
Debug(true, "printed\n")
Warning(false, "no warning")
Error(false, "no error")
Error(0, "no error either")
#write (Out, "done\n")
#fclose Out
