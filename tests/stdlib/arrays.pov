// Calls every macro of arrays.inc and writes the arrays they leave, one `name values..` line
// each, to probe.txt; tests/integration/includes.rs runs it with durer's embedded arrays.inc
// and compares the result with POV-Ray's output. (The density files ARRAYS_WriteDF3 writes
// are checked byte by byte in includes.rs.)
#version 3.7;
#include "arrays.inc"
#fopen Out "probe.txt" write
#macro Put(Name, Array)
  #write (Out, Name)
  #for (I, 0, dimension_size(Array, 1) - 1)
    #ifdef (Array[I])
      #write (Out, " ", vstr(3, <0, 0, 0> + Array[I], " ", 0, 6))
    #else
      #write (Out, " -")
    #end
  #end
  #write (Out, "\n")
#end

// Arrays of several lengths with repeated values, from a fixed stream.
#declare R = seed(42);
#for (Size, 1, 40, 3)
  #declare A = array[Size];
  #for (I, 0, Size - 1)
    #declare A[I] = floor(rand(R) * 12) - 4;
  #end
  #declare S = str(Size, 0, 0);
  #declare Picked = array[3];
  #for (I, 0, 2)
    #declare Picked[I] = (Rand_Array_Item(A, R));
  #end
  Put(concat("Rand_Array_Item ", S), Picked)
  Reverse_Array(A)
  Put(concat("Reverse_Array ", S), A)
  Sort_Array(A)
  Put(concat("Sort_Array ", S), A)
  Reverse_Array(A)
  Sort_Partial_Array(A, 1, Size - 2)
  Put(concat("Sort_Partial_Array ", S), A)
  Resize_Array(A, Size + 2)
  Put(concat("Resize_Array longer ", S), A)
  Resize_Array(A, floor(Size / 2) + 1)
  Put(concat("Resize_Array shorter ", S), A)
#end
#declare Holes = array[6] {1, 2, 3, 4, 5, 6}
Resize_Array(Holes, 9)
Resize_Array(Holes, 10)
Put("Resize_Array unassigned", Holes)
#declare Grid = array[2][3] {{0, 0.5, 1}, {0.25, 0.75, 0.1}}
ARRAYS_WriteDF3(Grid, "probe8.df3", 8)
ARRAYS_WriteDF3(Grid, "probe16.df3", 16)
#declare Line = array[4] {0.5, 1, 0, 0.2}
ARRAYS_WriteDF3(Line, "probe_line.df3", 8)
#ifndef (ARRAYS_Temp) #write (Out, "ARRAYS_Temp undefined again\n") #end

// Sorting vectors by x only, moving a second array along: the order of equal keys shows that
// the same pivots and swaps were made.
#declare Keys = array[30];
#declare Tags = array[30];
#for (I, 0, 29)
  #declare Keys[I] = <floor(rand(R) * 5), I, 0>;
  #declare Tags[I] = I * 10;
#end
#macro Sort_Compare(Array, IdxA, IdxB) (Array[IdxA].x < Array[IdxB].x) #end
#macro Sort_Swap_Data(Array, IdxA, IdxB)
  #local Key = Array[IdxA];
  #declare Array[IdxA] = Array[IdxB];
  #declare Array[IdxB] = Key;
  #local Tag = Tags[IdxA];
  #declare Tags[IdxA] = Tags[IdxB];
  #declare Tags[IdxB] = Tag;
#end
Sort_Array(Keys)
Put("Sort_Array keys", Keys)
Put("Sort_Array tags", Tags)
#write (Out, "next ", str(rand(ARRAYS_QuickSortSeed), 0, 9), " ", str(rand(R), 0, 9), "\n")
#fclose Out
