// Float, vector and string built-ins; expected values printed by POV-Ray 3.7.
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#macro Same(A, B) (strcmp(A, B) = 0) #end
// strcmp returns the difference of the first bytes that differ, as C does.
Check((strcmp("abc", "abd") = -1), "strcmp less")
Check((strcmp("abc", "ab") = 99), "strcmp with a shorter string")
Check((strcmp("", "x") = -120), "strcmp with an empty string")
Check((mod(-7, 3) = -1 & mod(7.5, 2) = 1.5 & div(-7, 2) = -3), "mod and div")
Check((bitwise_and(12, 10) = 8 & bitwise_or(12, 10, 1) = 15 & bitwise_xor(12.7, 10) = 6), "bitwise")
Check(Same(str(1.23456789, 0, -1), "1.234568"), "str with precision -1")
Check(Same(str(-1.5, -8, 2), "-0001.50"), "str with zero padding")
Check(Same(str(-1.5, 8, 2), "   -1.50"), "str with space padding")
Check(Same(str(2.5, 0, 0), "2"), "str rounds half to even")
Check(Same(vstr(2, <1,2,3>, ", ", 0, 1), "1.0, 2.0"), "vstr")
Check(Same(vstr(5, <1,2,3>, ",", 3, 1), "1.0,2.0,3.0,0.0,0.0"), "vstr past the vector's size")
Check(Same(vstr(3, 7, ",", 0, 0), "7,0,0"), "vstr of a float")
Check((val("  12.5abc") = 12.5 & val("abc") = 0 & val("-1e3x") = -1000), "val")
Check((val("0x10") = 16 & val(".5") = 0.5 & val("+4") = 4), "val of hex, fractions, signs")
Check((Same(concat(chr(65), chr(97)), "Aa") & asc("Z") = 90 & asc("") = 0), "chr and asc")
Check((Same(strupr("aBc1"), "ABC1") & Same(strlwr("AbC1"), "abc1") & Same(substr("Hello", 2, 3), "ell")), "case and substr")
Check((select(-1,1,2,3) = 1 & select(0,1,2,3) = 2 & select(1,1,2,3) = 3 & select(0,1,2) = 2), "select")
Check((int(-2.5) = -2 & floor(-2.5) = -3 & ceil(-2.5) = -2), "rounding")
Check((vlength(vrotate(x, <0,0,90>) - y) < 1e-12 & vlength(vaxis_rotate(x, z, 90) - y) < 1e-12), "rotations")
Check((max(1,5,3) = 5 & min(4,2,8) = 2), "min and max")
Check((!defined(Nope) & file_exists("colors.inc") & !file_exists("nope.inc")), "defined and file_exists")
Check((abs(rand(seed(0)) - 0.000002874) < 1e-9 & abs(rand(seed(-5)) - 0.890052870) < 1e-9), "rand")
// #ifdef on array elements: only assigned elements are defined.
#declare A = array[3];
#declare A[1] = 5;
#ifdef (A[1]) #declare Found = 1; #else #declare Found = 0; #end
Check(Found, "#ifdef on an assigned element")
#ifdef (A[0]) #error "#ifdef on an unassigned element" #end
// Comparisons: <= and >= accept differences below 1e-10, like =; < and > do not.
Check(((1 + 1e-11) <= 1 & 1 >= (1 + 1e-11) & (1 + 1e-11) = 1 & 1 < (1 + 1e-11)), "comparison epsilon")

// A function body that is a macro call expanding to a pigment is a pigment function, as
// `function { pigment { .. } }` (t-o-k's Gaussian_Blur.inc: `function { BlurPigment(..) }`).
#macro Half_Red_Pigment(Amount) pigment { rgb <Amount, 0.25, 0> } #end
#declare Pigment_From_Macro = function { Half_Red_Pigment(0.5) }
#if (abs(Pigment_From_Macro(0, 0, 0).red - 0.5) > 1e-6 | abs(Pigment_From_Macro(0, 0, 0).green - 0.25) > 1e-6)
  #error "function { Macro() } with a pigment-valued macro"
#end
#declare Constant_Two = function { 1 + 1 }
#if (Constant_Two(0, 0, 0) != 2) #error "a constant function body" #end
