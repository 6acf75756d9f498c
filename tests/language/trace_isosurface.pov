// `trace` on an isosurface lands where POV-Ray 3.7's does: on the far end of the last halving
// of the container span (past the surface by up to `accuracy`), and a ray starting inside the
// surface begins its search five accuracy steps out. Every expected value was printed by
// POV-Ray 3.7 (`-x + Offset` is a plane at x = Offset, inside towards +x).
#macro Check(Got, Expected, Message)
  #if (abs(Got - Expected) > 1e-12)
    #error concat("failed: ", Message, ": got ", str(Got, 0, 16), ", POV-Ray ", str(Expected, 0, 16))
  #end
#end
#macro TraceX(Offset, Half, Accuracy, From, Direction)
  #local Shape = isosurface {
    function { -x + Offset }
    contained_by { box { -Half, Half } }
    accuracy Accuracy
    max_gradient 1
  }
  #local Normal = <0, 0, 0>;
  #local Hit = trace(Shape, From, Direction, Normal);
  Hit.x
#end
// From outside: the far end of the bracketing halving of [-1, 1].
Check(TraceX(0, 1, 0.1, <-3, 0.3, 0.2>, x), 0.0625, "plane at 0, accuracy 0.1")
Check(TraceX(0.07, 1, 0.1, <-3, 0.3, 0.2>, x), 0.125, "plane at 0.07, accuracy 0.1")
Check(TraceX(0, 1, 0.3, <-3, 0.3, 0.2>, x), 0.25, "plane at 0, accuracy 0.3")
Check(TraceX(0.123, 1, 0.01, <-3, 0.3, 0.2>, x), 0.125, "plane at 0.123, accuracy 0.01")
Check(TraceX(0.3456, 1, 0.001, <-3, 0.3, 0.2>, x), 0.345703125, "plane at 0.3456, accuracy 0.001")
Check(TraceX(-0.9, 1, 0.1, <-3, 0.3, 0.2>, x), -0.875, "plane at -0.9, accuracy 0.1")
Check(TraceX(0.95, 1, 0.1, <-3, 0.3, 0.2>, x), 1, "plane at 0.95: the container")
// Halving goes on while the interval is not shorter than `accuracy`.
Check(TraceX(0.01, 1, 0.0625, <-3, 0.3, 0.2>, x), 0.03125, "interval exactly as long as accuracy 0.0625")
Check(TraceX(0.01, 1, 0.125, <-3, 0.3, 0.2>, x), 0.0625, "interval exactly as long as accuracy 0.125")
// From inside: the search starts 0.05 (5 x accuracy 0.01) along the ray.
Check(TraceX(0, 10, 0.01, <0.5, 0, 0>, -x), -0.0041259765625, "from 0.5 inside, box 10")
Check(TraceX(0, 1, 0.01, <0.5, 0, 0>, -x), -0.003125, "from 0.5 inside, box 1")
Check(TraceX(0, 1, 0.01, <0.065, 0, 0>, -x), -0.000859375, "from 0.065 inside")
Check(TraceX(0, 1, 0.001, <0.05, 0, 0>, -x), -0.00041259765625, "from 0.05 inside, accuracy 0.001")
Check(TraceX(0, 10, 0.01, <0.05, 0, 0>, -x), 0, "from 0.05 inside: the crossing is skipped")
Check(TraceX(0, 10, 0.01, <0.005, 0, 0>, <-0.1, 1, 0>), -0.000946889871, "grazing from inside")
