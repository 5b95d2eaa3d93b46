// Cylinders, cones, discs and tori, transformed, on a checkered floor, flat-lit (emission only,
// no lights): what a pixel shows is the colour where its centre ray meets a surface, so both
// the silhouettes and the hit points (through the patterns) are compared.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -11> look_at <0, 1, 0> angle 55 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.25 } finish { Flat } }
cylinder { <-4.5, 0, 2>, <-4.5, 2.5, 2>, 0.8
  pigment { gradient y colour_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.9>] } scale 2.5 }
  finish { Flat } }
cylinder { <-2.6, 0.6, 0>, <-1.2, 2.6, 1>, 0.6 open
  pigment { checker rgb <0.2, 0.8, 0.3>, rgb <0.9, 0.9, 0.2> scale 0.3 } finish { Flat } }
cone { <0, 0, 2>, 1.1, <0, 2.8, 2>, 0.3
  pigment { radial frequency 8 colour_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.2, 0.2, 0.8>] } }
  finish { Flat } }
cone { <2.2, 0.2, 0>, 0, <2.2, 2, 0.8>, 0.8 open
  pigment { rgb <0.6, 0.1, 0.7> } finish { Flat } }
disc { <4.5, 1.5, 1.5>, <0.4, 1, -1>, 1.2, 0.5
  pigment { onion colour_map { [0 rgb <0.1, 0.6, 0.6>] [1 rgb <0.9, 0.8, 0.5>] } scale 0.4 }
  finish { Flat } }
torus { 1.0, 0.35
  pigment { checker rgb <0.9, 0.3, 0.3>, rgb <0.3, 0.3, 0.9> scale 0.25 } finish { Flat }
  scale <1, 1.6, 1> rotate <60, 20, 0> translate <0.6, 1.5, -2.6> }
torus { 0.7, 0.2 pigment { rgb <0.2, 0.9, 0.9> } finish { Flat } translate <-3, 0.2, -2.2> }
