// Quadrics and polynomial surfaces (cubic, quartic, poly) cut to boxes and spheres, flat-lit
// (emission only, no lights) over a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -11> look_at <0, 1, 0> angle 55 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.25 } finish { Flat } }
// A hyperboloid of one sheet, x^2 + z^2 - y^2 = 0.25, cut to a box.
quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.25
  clipped_by { box { <-2, -1.2, -2>, <2, 1.2, 2> } }
  pigment { gradient y colour_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.9>] } scale 2.4 translate -1.2*y }
  finish { Flat } translate <-4, 1.3, 1.5> }
// A torus as a quartic: (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2), R = 1, r = 0.4.
#declare R2 = 1; #declare r2 = 0.16; #declare K = R2 - r2;
quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, 2*K - 4*R2,
           0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
           1, 0, 0, 2, 0, 2*K, 0, 0, 0, 0,
           1, 0, 2*K - 4*R2, 0, K*K>
  sturm
  bounded_by { box { <-1.5, -0.5, -1.5>, <1.5, 0.5, 1.5> } }
  pigment { checker rgb <0.9, 0.3, 0.3>, rgb <0.3, 0.3, 0.9> scale 0.25 } finish { Flat }
  rotate <50, 20, 0> translate <0, 1.5, 1.5> }
// A cubic saddle, y = x^3 - 3 x z^2 (the monkey saddle), cut to a cylinder.
cubic { <1, 0, 0, 0, 0, 0, -3, 0, 0, 0,
         0, 0, 0, 0, 0, -1, 0, 0, 0, 0>
  clipped_by { cylinder { -3*y, 3*y, 1.1 } }
  pigment { radial frequency 8 colour_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.2, 0.2, 0.8>] } }
  finish { Flat } scale 0.9 translate <3.6, 1.6, 1.2> }
// A sphere of radius 1 as a poly of order 2, and an infinite cylinder quadric, both cut.
poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1>
  pigment { onion colour_map { [0 rgb <0.1, 0.6, 0.6>] [1 rgb <0.9, 0.8, 0.5>] } scale 0.3 }
  finish { Flat } translate <-2, 1, -2.5> }
quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.36
  clipped_by { plane { y, 1.8 } } clipped_by { plane { -y, 0 } }
  pigment { rgb <0.6, 0.1, 0.7> } finish { Flat } translate <1.8, 0, -2.5> }
