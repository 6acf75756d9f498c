// Draws from every macro of rand.inc with a few arguments and writes the numbers, one
// `name values..` line each, to probe.txt; tests/integration/includes.rs runs it with durer's
// embedded rand.inc and compares the result with POV-Ray's output (same seeds, same numbers).
#version 3.7;
#include "rand.inc"
#fopen Out "probe.txt" write
#macro Put(Name, Value)
  #write (Out, Name, " ", vstr(3, <0, 0, 0> + (Value), " ", 0, 9), "\n")
#end

#declare Streams = array[4] {RdmA, RdmB, RdmC, RdmD}
#for (I, 0, 3)
  #declare R = Streams[I];
  #declare S = str(I, 0, 0);
  Put(concat("Prob ", S), <Prob(0.3, R), Prob(0.7, R), Prob(0.5, R)>)
  Put(concat("SRand RRand ", S), <SRand(R), RRand(-3, 8, R), RRand(2, 2.5, R)>)
  Put(concat("VRand ", S), VRand(R))
  Put(concat("VRand_In_Box ", S), VRand_In_Box(<-1, 0, 2>, <3, 0.5, 7>, R))
  Put(concat("VRand_In_Sphere ", S), VRand_In_Sphere(R))
  Put(concat("VRand_On_Sphere ", S), VRand_On_Sphere(R))
  Put(concat("Rand_Gauss ", S), <Rand_Gauss(2, 0.5, R), Rand_Gauss(0, 1, R), Rand_Gauss(-4, 3, R)>)
  Put(concat("Gauss_Next ", S), Gauss_Next)
  Put(concat("Rand_Normal ", S), <Rand_Normal(1, 2, R), Rand_Normal(0, 1, R), Rand_Normal(5, 0.1, R)>)
  Put(concat("Rand_Cauchy ", S), <Rand_Cauchy(1, 2, R), Rand_Cauchy(0, 0.5, R)>)
  Put(concat("Rand_Student ", S), <Rand_Student(3, R), Rand_Student(10.5, R)>)
  Put(concat("Rand_Gamma ", S), <Rand_Gamma(2.5, 1, R), Rand_Gamma(1, 2, R), Rand_Gamma(0.6, 3, R)>)
  Put(concat("Rand_Gamma large ", S), <Rand_Gamma(9, 0.5, R), Rand_Gamma(1.01, 1, R)>)
  Put(concat("Rand_Beta ", S), <Rand_Beta(2, 3, R), Rand_Beta(0.7, 0.9, R), Rand_Beta(1, 5, R)>)
  Put(concat("Rand_Chi_Square ", S), <Rand_Chi_Square(4, R), Rand_Chi_Square(7.9, R)>)
  Put(concat("Rand_F_Dist ", S), Rand_F_Dist(4, 6, R))
  Put(concat("Rand_Triangle ", S), <Rand_Triangle(0, 10, 3, R), Rand_Triangle(-1, 1, 1, R), Rand_Triangle(2, 4, 2, R)>)
  Put(concat("Rand_Erlang ", S), <Rand_Erlang(2, 3, R), Rand_Erlang(0.5, 1.5, R)>)
  Put(concat("Rand_Exp ", S), <Rand_Exp(0.5, R), Rand_Exp(3, R)>)
  Put(concat("Rand_Lognormal ", S), Rand_Lognormal(0.5, 0.25, R))
  Put(concat("Rand_Pareto ", S), <Rand_Pareto(1.5, R), Rand_Pareto(3, R)>)
  Put(concat("Rand_Weibull ", S), <Rand_Weibull(1, 1.5, R), Rand_Weibull(2, 0.5, R)>)
  Put(concat("Rand_Bernoulli ", S), <Rand_Bernoulli(0.25, R), Rand_Bernoulli(0.75, R), Rand_Bernoulli(1, R)>)
  Put(concat("Rand_Binomial ", S), <Rand_Binomial(10, 0.3, R), Rand_Binomial(7.8, 0.9, R)>)
  Put(concat("Rand_Geo ", S), <Rand_Geo(0.2, R), Rand_Geo(0.75, R)>)
  Put(concat("Rand_Poisson ", S), <Rand_Poisson(3, R), Rand_Poisson(0.5, R), Rand_Poisson(12, R)>)
#end

#declare Shape = spline { linear_spline 0, <0, 0.1, 0>, 0.5, <0, 1, 0>, 1, <0, 0.2, 0> }
#declare Ball = sphere { <1, 2, 3>, 1.5 }
#declare Ring = torus { 2, 0.25 rotate x * 30 }
#declare R = seed(1234);
#for (I, 0, 5)
  #declare S = str(I, 0, 0);
  Put(concat("Rand_Spline ", S), <Rand_Spline(Shape, R), cVal>)
  Put(concat("VRand_In_Obj ", S), VRand_In_Obj(Ball, R))
  Put(concat("VRand_In_Obj ring ", S), VRand_In_Obj(Ring, R))
#end
// What the streams draw next shows that each macro drew as often as POV-Ray's.
Put("next", <rand(RdmA), rand(RdmB), rand(RdmC)> + z * rand(RdmD) + x * rand(R))
#fclose Out
