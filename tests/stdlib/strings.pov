// Calls every macro of strings.inc and writes what each returns, one line each, to
// probe.txt; tests/integration/includes.rs runs it with durer's embedded strings.inc and
// compares the text with POV-Ray's output.
#version 3.7;
#include "strings.inc"
#fopen Out "probe.txt" write
#macro Put(Name, Text)
  #write (Out, Name, " [", Text, "]\n")
#end

#declare Numbers = array[6] {0, 1, -2.5, 0.1234567891, 12345.678, -0.000042}
#declare Colours = array[3] {
  rgbft <0.1, 0.25, 0.5, 0.75, 1>, rgb <1, 0.5, 0.2>, rgbt <-0.125, 2, 0.33, 0.5>
}
#for (I, 0, 5)
  #declare F = Numbers[I];
  #declare V = <F, 1 - F, F * 3>;
  Put("Str", Str(F))
  Put("VStr", VStr(V))
  Put("VStr2D", VStr2D(<F, -F>))
  #for (Length, 0, 8, 4)
    #for (Precision, -1, 3, 2)
      #declare S = concat(str(Length, 0, 0), " ", str(Precision, 0, 0));
      Put(concat("Vstr ", S), Vstr(V, Length, Precision))
      Put(concat("Vstr2D ", S), Vstr2D(V, Length, Precision))
    #end
  #end
  Put("Triangle_Str", Triangle_Str(V, V * 2, <F, 0, -1>))
  Put("Smooth_Triangle_Str", Smooth_Triangle_Str(V, y, V * 2, <0, F, 1>, x, <1, 1, F>))
#end
#for (I, 0, 2)
  #declare C = Colours[I];
  #for (Length, 0, 6, 6)
    #for (Precision, -1, 3, 2)
      #declare S = concat(str(Length, 0, 0), " ", str(Precision, 0, 0));
      Put(concat("CRGBStr ", S), CRGBStr(C, Length, Precision))
      Put(concat("CRGBFTStr ", S), CRGBFTStr(C, Length, Precision))
    #end
  #end
#end

// Parse_String runs its text as SDL, here a declaration and an object.
Parse_String("#declare Parsed = 6 * 7;")
Put("Parse_String", str(Parsed, 0, 0))
#declare Made = union { Parse_String(Triangle_Str(<0, 0, 0>, <1, 0, 0>, <0, 2, 1>)) }
Put("Parse_String object", concat(VStr(min_extent(Made)), VStr(max_extent(Made))))
#fclose Out
