// Bicubic patches: a saddle and a wave of 2^u_steps x 2^v_steps pieces (3 x 3, 4 x 2), a coarse
// one (1 x 1) that shows its facets, turned and scaled; on a checkered floor, flat-lit
// (emission only, no lights): silhouettes and hit points (through the patterns) are compared.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -11> look_at <0, 1, 0> angle 55 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
#declare Bands = pigment { gradient y colour_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.9>] }
                           scale 0.7 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.25 } finish { Flat } }
#declare Saddle = bicubic_patch { type 1 flatness 0 u_steps 3 v_steps 3
  <0, 0, 0>, <1, 1, 0>, <2, 1, 0>, <3, 0, 0>,
  <0, 1, 1>, <1, 2, 1>, <2, 0, 1>, <3, 1, 1>,
  <0, 1, 2>, <1, 0, 2>, <2, 2, 2>, <3, 1, 2>,
  <0, 0, 3>, <1, 1, 3>, <2, 1, 3>, <3, 0, 3> }
object { Saddle pigment { Bands } finish { Flat } translate <-5, 0.3, 0> }
bicubic_patch { type 0 flatness 0 u_steps 4 v_steps 2
  <0, 0, 0>, <1, 2, 0>, <2, -1, 0>, <3, 1, 0>,
  <0, 1, 1>, <1, 3, 1>, <2, 0, 1>, <3, 2, 1>,
  <0, 2, 2>, <1, 1, 2>, <2, 3, 2>, <3, 1, 2>,
  <0, 1, 3>, <1, 0, 3>, <2, 2, 3>, <3, 3, 3>
  pigment { checker rgb <0.2, 0.8, 0.3>, rgb <0.9, 0.9, 0.2> scale 0.3 } finish { Flat }
  rotate y*30 scale <1, 0.8, 1.2> translate <0, 0.5, 0> }
bicubic_patch { type 1 flatness 0 u_steps 1 v_steps 1
  <0, 0, 0>, <1, 1, 0>, <2, 1, 0>, <3, 0, 0>,
  <0, 1, 1>, <1, 2, 1>, <2, 0, 1>, <3, 1, 1>,
  <0, 1, 2>, <1, 0, 2>, <2, 2, 2>, <3, 1, 2>,
  <0, 0, 3>, <1, 1, 3>, <2, 1, 3>, <3, 0, 3>
  pigment { radial frequency 8 colour_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.2, 0.2, 0.8>] } }
  finish { Flat } rotate x*-30 translate <3, 0.5, -2.5> }
