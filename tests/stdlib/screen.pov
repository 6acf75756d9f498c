// Moves screen.inc's camera with each of its macros and writes the settings and camera frame
// after each, and the extents of objects pinned with Screen_Object and Screen_Plane, one
// `name values..` line each, to probe.txt; tests/integration/includes.rs runs it with
// durer's embedded screen.inc and compares the result with POV-Ray's output.
#version 3.7;
#declare Camera_Aspect_Ratio = 4 / 3; // not the probe image's
#include "screen.inc"
#fopen Out "probe.txt" write
#macro Put(Name, Value)
  #write (Out, Name, " ", vstr(3, <0, 0, 0> + (Value), " ", 0, 9), "\n")
#end
// Where Camera_Transform takes a point: the centre of a tiny box around it.
#macro Moved(Point)
  #local Dot = box { Point - 0.001, Point + 0.001 transform { Camera_Transform } }
  ((max_extent(Dot) + min_extent(Dot)) / 2)
#end
#macro Frame(Name)
  Put(concat(Name, " zoom aspect"), <Camera_Zoom, Camera_Aspect_Ratio, 0>)
  Put(concat(Name, " location"), Camera_Location)
  Put(concat(Name, " look_at"), Camera_Look_At)
  Put(concat(Name, " sky"), Camera_Sky)
  Put(concat(Name, " CamL"), CamL)
  Put(concat(Name, " CamD"), CamD)
  Put(concat(Name, " CamR"), CamR)
  Put(concat(Name, " CamU"), CamU)
  Put(concat(Name, " transform"), Moved(<0.3, -0.7, 2>))
#end
#macro Pinned(Name, Thing)
  Put(concat(Name, " min"), min_extent(Thing))
  Put(concat(Name, " max"), max_extent(Thing))
#end
#declare Block = box { <-0.2, -0.1, -0.3>, <0.4, 0.3, 0.1> }

Frame("default")
Set_Camera_Location(<1, 2, -5>) Frame("location")
Set_Camera_Look_At(<0, 1, 3>) Frame("look_at")
Set_Camera_Sky(<0.2, 1, 0.1>) Frame("sky")
Set_Camera_Zoom(1.7) Frame("zoom")
Set_Camera_Aspect_Ratio(2) Frame("aspect ratio")
Set_Camera_Aspect(640, 480) Frame("aspect")
Set_Camera_Angle(50) Frame("angle")
Pinned("confined corner", Screen_Object(Block, <0, 1>, 0.05, true, 0.01))
Pinned("free point", Screen_Object(Block, <0.3, 0.6>, 0.1, false, 0.5))
Pinned("centred", Screen_Object(Block, <0.5, 0.5>, 0, true, 1))
Pinned("plane", Screen_Plane(texture { pigment { rgb 1 } }, 0.1, <0.1, 0.2>, <0.6, 0.9>))
Set_Camera(<-3, 4, 2>, <1, 0, 0>, 65) Frame("set")
Pinned("plane after set", Screen_Plane(texture { pigment { rgb x } }, 1, <0, 0>, <1, 1>))
Reset_Camera()
Set_Camera_Aspect(3, 2) Frame("reset")
#fclose Out
