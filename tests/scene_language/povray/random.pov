// seed() and rand(): POV-Ray's own sequences, and the macros of rand.inc that use them.
#version 3.7;
#macro F(Label, V) #debug concat(Label, " ", str(V, 0, 12), "\n") #end
#macro V3(Label, V) #debug concat(Label, " ", vstr(3, V, ",", 0, 9), "\n") #end
#declare Seeds = array[8] {0, 1, 12345, -5, 2.7, 4294967303, 2147483647, -2147483648}
#for (I, 0, 7)
  #declare R = seed(Seeds[I]);
  #for (K, 1, 6) F(concat("s", str(I, 0, 0), " ", str(K, 0, 0)), rand(R)) #end
#end
#declare R1 = seed(7);
#declare R2 = seed(7);
F("interleave", rand(R1) - rand(R2) + rand(R1) * 0 + rand(R2) - rand(R1))
#include "rand.inc"
#declare RS = seed(4711);
#for (K, 1, 20) F(concat("SRand ", str(K, 0, 0)), SRand(RS)) #end
#for (K, 1, 20) F(concat("RRand ", str(K, 0, 0)), RRand(-3, 5, RS)) #end
#for (K, 1, 10) V3(concat("VRand ", str(K, 0, 0)), VRand(RS)) #end
#for (K, 1, 10) V3(concat("VRandBox ", str(K, 0, 0)), VRand_In_Box(<-1, 0, 2>, <1, 3, 5>, RS)) #end
#for (K, 1, 10) V3(concat("VRandSph ", str(K, 0, 0)), VRand_In_Sphere(RS)) #end
#for (K, 1, 10) V3(concat("VOnSph ", str(K, 0, 0)), VRand_On_Sphere(RS)) #end
#for (K, 1, 10) F(concat("Normal ", str(K, 0, 0)), Rand_Normal(2, 0.5, RS)) #end
#for (K, 1, 10) F(concat("Gauss ", str(K, 0, 0)), Rand_Gauss(2, 0.5, RS)) #end
#for (K, 1, 10) F(concat("Exp ", str(K, 0, 0)), Rand_Exp(1.5, RS)) #end
#for (K, 1, 10) F(concat("Tri ", str(K, 0, 0)), Rand_Triangle(0, 10, 3, RS)) #end
#for (K, 1, 10) F(concat("Cauchy ", str(K, 0, 0)), Rand_Cauchy(0, 1, RS)) #end
#for (K, 1, 10) F(concat("Poisson ", str(K, 0, 0)), Rand_Poisson(3, RS)) #end
#for (K, 1, 10) F(concat("Binom ", str(K, 0, 0)), Rand_Binomial(10, 0.3, RS)) #end
#for (K, 1, 10) F(concat("Geo ", str(K, 0, 0)), Rand_Geo(0.3, RS)) #end
#for (K, 1, 10) F(concat("Prob ", str(K, 0, 0)), Prob(0.4, RS)) #end
#for (K, 1, 10) F(concat("Logn ", str(K, 0, 0)), Rand_Lognormal(1, 0.5, RS)) #end
#for (K, 1, 10) F(concat("Weib ", str(K, 0, 0)), Rand_Weibull(2, 1.5, RS)) #end
#for (K, 1, 10) F(concat("Pareto ", str(K, 0, 0)), Rand_Pareto(3, RS)) #end
#for (K, 1, 10) F(concat("Erlang ", str(K, 0, 0)), Rand_Erlang(2, 3, RS)) #end
#for (K, 1, 10) F(concat("Gamma ", str(K, 0, 0)), Rand_Gamma(2, 1.5, RS)) #end
#for (K, 1, 10) F(concat("Beta ", str(K, 0, 0)), Rand_Beta(2, 3, RS)) #end
#for (K, 1, 10) F(concat("Chi ", str(K, 0, 0)), Rand_Chi_Square(4, RS)) #end
#for (K, 1, 10) F(concat("Student ", str(K, 0, 0)), Rand_Student(5, RS)) #end
#for (K, 1, 10) F(concat("FDist ", str(K, 0, 0)), Rand_F_Dist(3, 4, RS)) #end
#for (K, 1, 10) F(concat("Bern ", str(K, 0, 0)), Rand_Bernoulli(0.3, RS)) #end
