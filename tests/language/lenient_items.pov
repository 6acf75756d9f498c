// Items POV-Ray 3.7 reads more leniently than its manual says, as real scenes write them;
// each was checked with povray (this file parses there too).
#version 3.7;
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end

// A value that cannot be called, then a parenthesised float: two items, not a call.
#declare Down = plane { y (-1) }
Check((vlength(trace(Down, <0, 5, 0>, -y) - <0, -1, 0>) < 1e-9), "`y (-1)` is a normal and a distance")
#declare V = <0, 0, 1>;
#declare Back = plane { V (2) }
Check((inside(Back, <0, 0, 1.5>) & !inside(Back, <0, 0, 2.5>)), "a vector identifier, then a float in parentheses")

// Pigment, finish and normal identifiers straight inside `texture`, before its other items.
#declare P = pigment { rgb <1, 0, 0> }
#declare F = finish { phong 1 }
#declare N = normal { bumps 0.5 }
#declare T1 = texture { P F N }
#declare T2 = texture { T1 P scale 2 }
#declare T3 = texture { N P F }
sphere { 0, 1 texture { T2 } }

// Any shape or CSG block may start with a declared object of any kind, as `object { }` does.
#declare Small = sphere { 0, 0.5 }
#declare Grown = sphere { Small scale 2 }
Check((abs(max_extent(Grown).x - 1) < 1e-6), "`sphere { Small scale 2 }` is Small scaled")
#declare Cube = box { -0.5, 0.5 }
#declare Boxed = sphere { Cube }
Check(inside(Boxed, <0.45, 0.45, 0.45>), "`sphere { Cube }` is the box")
#declare Moved = union { Small translate x }
Check((abs(min_extent(Moved).x - 0.5) < 1e-6), "`union { Small translate x }` is Small moved")
#declare Lamp = light_source { <0, 3, -3> rgb 1 }
cylinder { Lamp }

// `#undef` of one array element leaves it uninitialised.
#declare Arr = array[2] { 1, 2 }
#undef Arr[1]
#ifdef (Arr[1]) #error "failed: `#undef Arr[1]` leaves the element" #end
#ifndef (Arr[0]) #error "failed: `#undef Arr[1]` removes the other element" #end
#declare Arr[1] = 5;
Check((Arr[1] = 5), "an undefined element can be set again")

// An image file named without its extension: POV-Ray tries the type's extension.
#declare Picture = pigment { image_map { png "lenient_picture" } }
#declare Heights = height_field { png "lenient_picture" }
Check((max_extent(Heights).y > 0.1), "the height field read the image")

// A function (or spline) stored in an array is called with `Fns[I](x)`, in scene code and
// inside functions; an element that cannot be called is an item followed by a parenthesis.
#declare Fns = array[2] { function(x) { x * 2 }, function(x) { x + 10 } }
#declare I = 1;
Check((Fns[I](3) = 13), "`Fns[I](3)` calls the second function")
Check((Fns[0](3) + 1 = 7), "`Fns[0](3) + 1`")
#declare Doubled = function(x) { Fns[1](x) * 2 }
Check((Doubled(1) = 22), "`Fns[1](x)` inside a function")
#declare Grid = array[1][2] { { function { x + y }, function { x - y } } }
Check((Grid[0][1](5, 2, 0) = 3), "a function in a two-dimensional array")
#declare Paths = array[1] { spline { linear_spline 0, <0, 0, 0>, 1, <2, 4, 6> } }
Check((vlength(Paths[0](0.5) - <1, 2, 3>) < 1e-9), "a spline in an array")
#declare Normals = array[1] { <0, 1, 0> }
#declare Floor = plane { Normals[0] (-1) }
Check((inside(Floor, <0, -1.5, 0>) & !inside(Floor, <0, -0.5, 0>)), "`Normals[0] (-1)` is a normal and a distance")

// Directives between `#declare A =` and its value run first; `#switch` may be the value.
#declare Base = 3;
#declare Sum =
  #declare Base = Base + 1;
  #debug ""
  Base * 2;
Check((Sum = 8 & Base = 4), "directives before a declared value run first")
#local Picked =
#switch (Base)
  #case (4) texture { pigment { rgb <1, 0, 0> } } #break
  #else texture { pigment { rgb 0 } }
#end
sphere { 0, 1 texture { Picked } }

// `#include` of a name without an extension reads NAME.inc, as povray tries.
#include "lenient_without_extension"
Check(FromExtensionless, "the include without an extension read lenient_without_extension.inc")

// A colour vector shorter than its type asks for has the missing components 0.
#declare Short = rgbf <1, 0.5, 0.2>;
Check((Short.filter = 0 & abs(Short.blue - 0.2) < 1e-6), "`rgbf <r, g, b>` has filter 0")
#declare Pair = rgb <1, 0.5>;
Check((Pair.blue = 0), "`rgb <r, g>` has blue 0")
// A longer one keeps its extra components (povray warns "Suspicious expression after rgb"):
// `rgb <r, g, b, f, t>` has that filter and transmit, `rgbf` keeps a fifth as transmit,
// `rgbt` takes the fourth as transmit and drops a fifth; a colour after `rgb` is all of it.
#declare Long4 = rgb <0.1, 0.2, 0.3, 0.7>;
Check((abs(Long4.filter - 0.7) < 1e-6 & Long4.transmit = 0), "`rgb <r, g, b, f>` keeps the filter")
#declare Long5 = rgbf <0.1, 0.2, 0.3, 0.7, 0.8>;
Check((abs(Long5.filter - 0.7) < 1e-6 & abs(Long5.transmit - 0.8) < 1e-6), "`rgbf` keeps a fifth as transmit")
#declare LongT = rgbt <0.1, 0.2, 0.3, 0.7, 0.8>;
Check((LongT.filter = 0 & abs(LongT.transmit - 0.7) < 1e-6), "`rgbt` takes the fourth as transmit")
#declare Whole = rgbft <0.1, 0.2, 0.3, 0.4, 0.5>;
#declare Again = rgb Whole;
Check((abs(Again.filter - 0.4) < 1e-6 & abs(Again.transmit - 0.5) < 1e-6), "`rgb Colour` is the whole colour")
// Colour components in a pigment modify a colour right before them; anywhere else (after a
// pigment identifier, first in a pigment modifying a texture's) they start from black.
#declare GreenP = pigment { rgb <0, 1, 0> }
#declare Clear = pigment { GreenP transmit 0.5 }
#declare ClearF = function { pigment { Clear } }
#declare ClearC = ClearF(0, 0, 0);
Check((ClearC.green = 0 & abs(ClearC.transmit - 0.5) < 1e-6), "`pigment { P transmit 0.5 }` is black with transmit 0.5")
#declare NamedRed = rgb <1, 0, 0>;
#declare Kept = pigment { NamedRed green 0.5 }
#declare KeptF = function { pigment { Kept } }
#declare KeptC = KeptF(0, 0, 0);
Check((KeptC.red = 1 & abs(KeptC.green - 0.5) < 1e-6), "`pigment { Colour green 0.5 }` modifies that colour")
// A second diffuse value without its comma (Blender's exporter writes `diffuse 0.8 0`).
#declare Matte = finish { diffuse 0.8 0 ambient 0.1 }

// `light_source { Object_Ident .. }` is that object, as `object { }` (a lamp union with its light).
#declare LampUnion = union { light_source { <0, 3, 0> rgb 1 } sphere { 0, 0.5 } }
// (povray gives such a union infinite extents and refuses it to `inside`, so it is only placed.)
light_source { LampUnion translate 2*x }

// `no_bump_scale` written in the texture itself (after the normal and its scale, as
// POV-Ray-Object-Collection's GameSprites write it) is read, as POV-Ray reads it.
#declare Walls = texture { pigment { rgb 0.5 } normal { bumps 0.3 scale 0.2 } scale 8 no_bump_scale }
#declare WallsFirst = texture { no_bump_scale pigment { rgb 0.5 } normal { bumps 0.3 } scale 8 }
sphere { 0, 1 texture { Walls } }

// `cutaway_textures` after the children of a difference or an intersection.
difference { sphere { 0, 1 pigment { rgb 1 } } box { 0, 2 } cutaway_textures }
intersection { sphere { 0, 1 pigment { rgb 1 } } box { 0, 2 } cutaway_textures }

// `looks_like` and `projected_through` read an `object { }` body: a declared object may be
// followed by object modifiers (the light's later transformations move both objects with
// it: reference scene light_projected_through_moved).
#declare Bulb = sphere { 0, 0.25 }
#declare Lamp = union {
  sphere { 0, 0.1 }
  light_source { <0, 2, 0>, rgb 1 looks_like { Bulb translate 0.5 * x } projected_through { Bulb scale 2 translate 2 * y } }
  translate 3 * x
}
object { Lamp }
