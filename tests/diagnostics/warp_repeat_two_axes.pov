// error: 5:10 the `repeat` direction must lie along one axis

#version 3.7;
plane { y, 0 pigment { checker rgb 1, rgb 0
  warp { repeat <1, 1, 0> } } }
