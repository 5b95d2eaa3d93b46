// Deterministic patterns POV-Ray documents only by pictures, at random points: spiral1 (arms,
// wave and transform), mandel and julia (escape times), through pattern functions.
#version 3.7;
#declare S = seed(11);
#declare Spiral = function { pattern { spiral1 3 } }
#declare Turned = function { pattern { spiral1 -2 ramp_wave scale 0.7 rotate x*30 } }
#declare Mandel = function { pattern { mandel 25 } }
#declare Julia = function { pattern { julia <0.353, 0.288>, 30 scale 1.5 } }
#for (I, 1, 80)
  #declare P = <rand(S) * 6 - 3, rand(S) * 6 - 3, rand(S) * 6 - 3>;
  #debug concat(str(Spiral(P.x, P.y, P.z), 0, 6), " ", str(Turned(P.x, P.y, P.z), 0, 6), " ",
                str(Mandel(P.x, P.y, P.z), 0, 6), " ", str(Julia(P.x, P.y, P.z), 0, 6), "\n")
#end
