// Surfaces of revolution (closed and open, a vase whose r^2 dips, turned and scaled unevenly,
// one cut from a box) and polygons (a square with a square hole, a self-crossing star, tilted);
// on a checkered floor, flat-lit (emission only, no lights): silhouettes and hit points
// (through the patterns) are compared.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -11> look_at <0, 1, 0> angle 55 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
#declare Bands = pigment { gradient y colour_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.9>] }
                           scale 0.7 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.25 } finish { Flat } }
sor { 6, <0.5, -1>, <1, 0>, <1.4, 0.8>, <0.5, 1.8>, <0.8, 2.3>, <1.2, 3>
  pigment { Bands } finish { Flat } translate <-4.5, 0, 2> }
sor { 5, <0, -0.5>, <0.9, 0>, <0.3, 1>, <0.9, 2>, <1, 2.5> open
  pigment { checker rgb <0.2, 0.8, 0.3>, rgb <0.9, 0.9, 0.2> scale 0.3 } finish { Flat }
  rotate z*25 scale <1, 0.8, 1.3> translate <-1.5, 0.6, 2> }
difference {
  box { <-1, 0, -1>, <1, 2, 1> }
  sor { 4, <0.2, -0.5>, <0.7, 0>, <0.9, 2>, <0.3, 2.5> }
  pigment { checker rgb <0.1, 0.6, 0.6>, rgb <0.9, 0.8, 0.5> scale 0.35 } finish { Flat }
  rotate y*-25 translate <1.8, 0, 2> }
polygon { 10, <-1, 0>, <1, 0>, <1, 2>, <-1, 2>, <-1, 0>, <-0.5, 0.5>, <0.5, 0.5>, <0.5, 1.5>,
  <-0.5, 1.5>, <-0.5, 0.5>
  pigment { radial frequency 8 colour_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.2, 0.2, 0.8>] } }
  finish { Flat } rotate y*20 translate <4.6, 0.2, 2> }
polygon { 6, <0, 1>, <0.59, -0.81>, <-0.95, 0.31>, <0.95, 0.31>, <-0.59, -0.81>, <0, 1>
  pigment { rgb <0.6, 0.1, 0.7> } finish { Flat } rotate x*-60 rotate y*30 translate <-3, 1.2, -1.5> }
polygon { 4, <0, 0, 0>, <1.5, 0, 0.2>, <0.8, 1.2, 1>, <0, 0, 0>
  pigment { Bands } finish { Flat } translate <1.2, 0.3, -2> }
