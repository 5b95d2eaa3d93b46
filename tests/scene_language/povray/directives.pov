// Macros, scopes and directives: parameters by reference, #local in macros and includes,
// recursion, macros as values, #switch fall-through, #for, #while, #break, #undef, #ifdef.
#version 3.7;
#macro F(Label, V) #debug concat(Label, " ", str(V, 0, 6), "\n") #end
#macro Inc(P) #declare P = P + 1; #end
#declare A = 5; Inc(A) Inc(A) F("byref", A)
#macro IncLocal(P) #local P = P + 10; #end
#declare B = 1; IncLocal(B) F("byref-local", B)
#macro ByValue(P) #declare P = P * 100; #end
#declare C = 2; ByValue(C + 0) F("byvalue", C)
#macro Twice(X) (2 * (X)) #end
F("value-macro", Twice(3) + Twice(Twice(1)))
#macro Local3(X) #local Y = X * 3; Y #end
F("local-return", Local3(4) + 1)
// A directive right after an operand ends POV-Ray's expression, so recursive macros return a
// #local rather than an expression that an #else follows.
#macro Fact(N) #if (N <= 1) #local R = 1; #else #local R = N * Fact(N - 1); #end R #end
F("fact10", Fact(10))
#macro Fib(N) #if (N < 2) #local R = N; #else #local R = Fib(N - 1) + Fib(N - 2); #end R #end
F("fib15", Fib(15))
#macro Shadow(X) #local A = X; A #end
F("shadow", Shadow(42) + A)
#declare G = 1;
#macro SetG(V) #declare G = V; #end
SetG(7) F("global", G)
#macro NewGlobal() #declare Fresh = 99; #end
NewGlobal() F("fresh", Fresh)
#macro Sw(V)
  #local R = 0;
  #switch (V)
    #case (1) #local R = R + 1;
    #case (2) #local R = R + 10; #break
    #range (3, 4.5) #local R = R + 100;
    #else #local R = R + 1000;
  #end
  R
#end
#for (I, 0, 6) F(concat("switch ", str(I, 0, 0)), Sw(I)) #end
#for (I, 1, 10, 3) F("for", I) #end
F("for-after", I)
#for (J, 5, 1, -2) F("down", J) #end
#for (K, 0, 1, 0.25) F("frac", K) #end
#for (K, 1, 10) #if (K = 4) #break #end F("brk", K) #end
#declare N = 0;
#while (1) #declare N = N + 1; #if (N >= 5) #break #end #end
F("while-break", N)
#macro Early(X) #local R = 1; #if (X) #break #end #local R = 2; #end
Early(0) Early(1) F("early", 1)
#declare U = 3; #undef U
#ifdef (U) F("undef", 1) #else F("undef", 0) #end
#ifndef (U) F("ifndef", 1) #end
#declare Arr = array[3];
#declare Arr[1] = 5;
#ifdef (Arr[0]) F("arr0", 1) #else F("arr0", 0) #end
#ifdef (Arr[1]) F("arr1", 1) #else F("arr1", 0) #end
F("defined", defined(Arr[1]) + 2 * defined(Nope) + 4 * defined(Arr))
#if (0) F("if", 1) #elseif (0) F("if", 2) #elseif (1) F("if", 3) #else F("if", 4) #end
#if (1) #if (0) #else F("nested", 5) #end #end
#declare Count = 0;
#while (Count < 3)
  #declare Inner = 0;
  #while (Inner < Count) #declare Inner = Inner + 1; #end
  F("loops", Count * 10 + Inner)
  #declare Count = Count + 1;
#end
#declare V = version;
#version 3.5;
F("version", version)
#version V;
F("version-restored", version)
F("clock", clock + clock_delta + clock_on + frame_number + initial_frame + final_frame)
#macro Recurse(D) #if (D > 0) Recurse(D - 1) #else F("depth", 60) #end #end
Recurse(60)
// A #local whose value is a macro call ending where the value ends binds in the caller's
// scope, not in the called macro's (gone at its #end).
#macro Text() "abc" #end
#macro Outer() #local X = Text() #local Y = 1; concat(X, "!") #end
#debug concat("local-from-macro ", Outer(), "\n")
