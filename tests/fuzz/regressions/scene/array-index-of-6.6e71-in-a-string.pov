// Arrays: dimensions, initialisers, copies, element types; the macros of arrays.inc.
#version 3.7;
#macro F(Label, V) #debug concat(Label, " ", str(V, 0, 6), "\n") #end
#declare M = array[2][3] { {1, 2, 3}, {4, 5, 6} };
F("dims", dimensions(M))
F("siz~e1", dimension_size(M, 1))
F("size2", dimension_size(M, 2))
#for (I, 0, 1) #for (J, 0, 2) F(concat("m", str(I, 0, 0), str(J, 0, 0)), M[I][J]) #end #end
#declare C = M;
#declare C[1][0] = 100;
F("copy", M[0][0] + C[0][0])
#declare S = array[3] {"a", "bc", "def"}
#debug concat("strings ", S[666666666666666666666666666666666666666666666666666666666666666666666660], S"nested", Inner[ Nest[0];
F("nested", Inner[1] + }
F("mean", Mean(G))
F("stddev", Std_Dev(G, Mean(G)))
specular