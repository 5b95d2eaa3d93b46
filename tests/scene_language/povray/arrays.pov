// Arrays: dimensions, initialisers, copies, element types; the macros of arrays.inc.
#version 3.7;
#macro F(Label, V) #debug concat(Label, " ", str(V, 0, 6), "\n") #end
#declare M = array[2][3] { {1, 2, 3}, {4, 5, 6} };
F("dims", dimensions(M))
F("size1", dimension_size(M, 1))
F("size2", dimension_size(M, 2))
#for (I, 0, 1) #for (J, 0, 2) F(concat("m", str(I, 0, 0), str(J, 0, 0)), M[I][J]) #end #end
#declare C = M;
#declare C[0][0] = 100;
F("copy", M[0][0] + C[0][0])
#declare S = array[3] {"a", "bc", "def"}
#debug concat("strings ", S[0], S[1], S[2], "\n")
#declare V = array[2] {<1, 2, 3>, <4, 5, 6>}
F("vec", V[1].y + V[0].z)
#declare Nest = array[2];
#declare Nest[0] = array[2] {7, 8};
#declare Nest[1] = array[1] {9};
#declare Inner = Nest[0];
F("nested", Inner[1] + dimension_size(Nest[1], 1))
#macro Sum(Arr) #local T = 0; #for (I, 0, dimension_size(Arr, 1) - 1) #local T = T + Arr[I]; #end T #end
#declare D = array[5] {3, 1, 4, 1, 5}
F("sum", Sum(D))
#include "arrays.inc"
#declare E = array[9] {9, -2, 7.5, 0, 3, 3, -8, 12, 1}
Sort_Array(E)
#for (I, 0, 8) F(concat("sorted ", str(I, 0, 0)), E[I]) #end
Reverse_Array(E)
#for (I, 0, 8) F(concat("reversed ", str(I, 0, 0)), E[I]) #end
Resize_Array(E, 4)
F("resized", dimension_size(E, 1) + E[3])
#declare P = array[6] {5, 4, 3, 2, 1, 0}
Sort_Partial_Array(P, 1, 4)
#for (I, 0, 5) F(concat("partial ", str(I, 0, 0)), P[I]) #end
#include "math.inc"
#declare G = array[6] {2, 4, 4, 4, 5, 5}
F("mean", Mean(G))
F("stddev", Std_Dev(G, Mean(G)))
