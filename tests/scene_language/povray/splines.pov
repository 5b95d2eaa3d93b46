// Splines of every kind on unevenly spaced parameters, with 2 to 5 terms, evaluated inside
// and outside their range and as another kind.
#version 3.7;
#macro P(Label, S, T) #debug concat(Label, " ", str(T, 0, 3), " ", vstr(5, S(T), ",", 0, 9), "\n") #end
#declare Ts = array[14] {-1, 0, 0.3, 1, 1.7, 2.5, 3, 3.25, 3.9, 4, 5.5, 6.9, 7, 8}
#declare L = spline { linear_spline 0, <1,0,0,0,0> 1, <0,1,0,0,0> 3, <0,0,1,0,0> 4, <0,0,0,1,0> 7, <0,0,0,0,1> }
#declare Q = spline { quadratic_spline 0, <1,0,0,0,0> 1, <0,1,0,0,0> 3, <0,0,1,0,0> 4, <0,0,0,1,0> 7, <0,0,0,0,1> }
#declare C = spline { cubic_spline 0, <1,0,0,0,0> 1, <0,1,0,0,0> 3, <0,0,1,0,0> 4, <0,0,0,1,0> 7, <0,0,0,0,1> }
#declare N = spline { natural_spline 0, <1,0,0,0,0> 1, <0,1,0,0,0> 3, <0,0,1,0,0> 4, <0,0,0,1,0> 7, <0,0,0,0,1> }
#for (I, 0, 13) P("lin", L, Ts[I]) #end
#for (I, 0, 13) P("quad", Q, Ts[I]) #end
#for (I, 0, 13) P("cub", C, Ts[I]) #end
#for (I, 0, 13) P("nat", N, Ts[I]) #end
#declare Path = spline {
  cubic_spline
  -1, <0, 0, 0>, 0, <1, 2, 0>, 0.5, <2, -1, 1>, 2, <3, 3, -2>, 2.2, <4, 0, 0>, 4, <5, 1, 1>
}
#for (I, -2, 22) #declare T = I / 5; #debug concat("path ", str(T, 0, 2), " ", vstr(3, Path(T), ",", 0, 9), "\n") #end
#for (I, -2, 22) #declare T = I / 5; #debug concat("path-nat ", str(T, 0, 2), " ", vstr(3, Path(T, natural_spline), ",", 0, 9), "\n") #end
#for (I, -2, 22) #declare T = I / 5; #debug concat("path-quad ", str(T, 0, 2), " ", vstr(3, Path(T, quadratic_spline), ",", 0, 9), "\n") #end
#declare Two = spline { cubic_spline 0, <0, 0>, 1, <1, 1> }
#debug concat("two ", vstr(2, Two(0.5), ",", 0, 9), "\n")
#declare Three = spline { natural_spline 0, <0, 0>, 1, <1, 1>, 2, <0, 3> }
#debug concat("three ", vstr(2, Three(0.5), ",", 0, 9), " ", vstr(2, Three(1.5), ",", 0, 9), "\n")
#declare Unordered = spline { linear_spline 2, <2, 2>, 0, <0, 0>, 1, <5, 5>, 1, <1, 1> }
#debug concat("unordered ", vstr(2, Unordered(0.5), ",", 0, 9), " ", vstr(2, Unordered(1.5), ",", 0, 9), "\n")
#declare Mixed = spline { linear_spline 0, 1, 1, <1, 2, 3, 4, 5> }
#debug concat("mixed ", vstr(5, Mixed(0.5), ",", 0, 9), "\n")
#declare Copy = spline { Path linear_spline }
#debug concat("copy ", vstr(3, Copy(1), ",", 0, 9), "\n")
#declare SF = function { spline { Path } }
#debug concat("fn ", vstr(3, SF(1.3), ",", 0, 9), "\n")
