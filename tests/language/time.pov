// `now` and `datetime`; expected strings printed by POV-Ray 3.7.
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#macro Same(A, B) (strcmp(A, B) = 0) #end
Check((now > 9000), "now counts days since 2000")
Check((strlen(datetime(now)) = 20), "the default format")
Check(Same(datetime(0), "2000-01-01 00:00:00Z"), "the epoch")
Check(Same(datetime(-400.25), "1998-11-26 18:00:00Z"), "before 2000")
Check(Same(datetime(9000.999999), "2024-08-23 00:00:00Z"), "rounded to the second")
#declare T = 1.5 + 13/24 + 5/1440 + 7/86400;
Check(Same(datetime(T, "%a %A %b %B"), "Mon Monday Jan January"), "names")
Check(Same(datetime(T, "%c"), "Mon Jan  3 01:05:07 2000"), "%c")
Check(Same(datetime(T, "%d %H %I %j %m %M %p %S"), "03 01 01 003 01 05 AM 07"), "numbers")
Check(Same(datetime(T, "%U %w %W %x %X %y %Y %%"), "01 1 01 01/03/00 01:05:07 00 2000 %"), "weeks")
Check(Same(datetime(T, "%q %Ey %5Y abc%"), "%q 00 02000 abc%"), "unknown codes and widths")
