// A file the scene rewrites with #fopen is read again by the next #include of it, as
// strings.inc's Parse_String needs (durer otherwise parses each include file once).
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#macro Run(Text)
  #fopen Script "include_rewritten.tmp" write
  #write (Script, Text)
  #fclose Script
  #include "include_rewritten.tmp"
#end
Run("#declare Answer = 1;")
Check(Answer = 1, "the first text runs")
Run("#declare Answer = Answer + 41;")
Check(Answer = 42, "the rewritten text runs, not the first one again")
#fopen More "include_rewritten.tmp" append
#write (More, "#declare Answer = Answer * 2;")
#fclose More
#include "include_rewritten.tmp"
Check(Answer = 166, "appending counts as rewriting: both lines run again")
