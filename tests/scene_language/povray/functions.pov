// User-defined functions: parameters, constants, nesting, sum/prod, select, logic; transform,
// spline and (solid) pigment functions; functions passed to macros.
#version 3.7;
#macro F(Label, V) #debug concat(Label, " ", str(V, 0, 9), "\n") #end
#declare K = 2.5;
#declare Fa = function(a, b) { a * b + sin(a) - K }
#declare Fb = function { x + y * z }
#declare Fc = function(u, v) { x + v * 2 }
#declare Fd = function(n) { prod(i, 1, n, i) + sum(k, 1, 3, k * k) }
#declare Fe = function(s) { select(s, -1, 0, 1) + select(s - 1, 10, 20) }
#declare Ff = function(p, q) { (p < q) + (p <= q) * 2 + (p = q) * 4 + (p != q) * 8 + (p & q) * 16 + (p | 0) * 32 }
#declare Fg = function(x, y, z) { Fa(x, y) + Fb(z, x, y) * 2 }
#declare Fh = function(a) { abs(a) + floor(a) + ceil(a) + int(a) + mod(a, 0.75) + pow(abs(a), 1.5) + exp(-a) }
#declare Fi = function(a) { sqrt(abs(a)) + ln(abs(a) + 1) + log(abs(a) + 2) + atan2(a, 2) + max(a, 1, -3) + min(a, 0.5) }
#declare Fj = function(a) { sinh(a) + cosh(a) + tanh(a) + asinh(a) + degrees(a) + radians(a) + tan(a / 4) }
#declare Fk = function(a, b) { -b + +a * 2 - -a }
#for (I, -4, 4)
  #declare X = I * 0.37;
  F(concat("Fa ", str(I, 0, 0)), Fa(X, 1.5))
  F(concat("Fb ", str(I, 0, 0)), Fb(X, 2, -X))
  F(concat("Fc ", str(I, 0, 0)), Fc(X, 3))
  F(concat("Fe ", str(I, 0, 0)), Fe(X))
  F(concat("Ff ", str(I, 0, 0)), Ff(X, 0.37))
  F(concat("Fg ", str(I, 0, 0)), Fg(X, 0.5, 2))
  F(concat("Fh ", str(I, 0, 0)), Fh(X))
  F(concat("Fi ", str(I, 0, 0)), Fi(X))
  F(concat("Fj ", str(I, 0, 0)), Fj(X))
  F(concat("Fk ", str(I, 0, 0)), Fk(X, 0.5))
#end
#for (N, 0, 6) F(concat("Fd ", str(N, 0, 0)), Fd(N)) #end
#declare T = function { transform { rotate <30, 45, 60> scale <1, 2, 3> translate <-1, 0, 1> } }
#debug concat("T ", vstr(3, T(1, 2, 3), ",", 0, 9), "\n")
#declare TI = function { transform { rotate <30, 45, 60> scale 2 inverse } }
#debug concat("TI ", vstr(3, TI(1, 2, 3), ",", 0, 9), "\n")
#declare P = function { pigment { rgb <0.2, 0.4, 0.6> } }
#debug concat("P ", vstr(5, P(1, 2, 3), ",", 0, 6), "\n")
F("Pgray", P(0, 0, 0).gray)
#declare Pf = function(a) { P(a, 0, 0).green * a }
F("Pf", Pf(3))
#macro Apply(Fn, V) Fn(V, V, V) #end
F("apply", Apply(Fb, 2))
#declare Sp = spline { natural_spline 0, <0, 0, 0>, 1, <1, 4, 9>, 2, <2, 1, 0>, 3, <0, 0, 5> }
#declare Sf = function { spline { Sp } }
#declare Sx = function(s) { Sf(s).y * 2 }
F("spline-fn", Sx(1.5))
