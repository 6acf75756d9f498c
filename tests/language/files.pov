// #fopen, #write, #read, #fclose on a data file next to the scene.
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#fopen Out "files_data.tmp" write
#write (Out, "1.5, <1,2,3>, \"word\",\n", 7, "\n")
#fclose Out
#fopen In "files_data.tmp" read
#read (In, A, V, S, B)
Check(A = 1.5, "read a float")
Check(V.y = 2, "read a vector")
Check(strcmp(S, "word") = 0, "read a string")
Check(B = 7, "read the last float")
Check(!defined(In), "the handle is undefined at the end of the file")
#fclose In // closing an already undefined handle is allowed, as in POV-Ray
#fopen Again "files_data.tmp" append
#write (Again, 8)
#fclose Again
#declare Count = 0;
#fopen In2 "files_data.tmp" read
#while (defined(In2))
  #read (In2, Item)
  #declare Count = Count + 1;
#end
Check(Count = 5, "append adds to the end; a loop reads until the handle disappears")
