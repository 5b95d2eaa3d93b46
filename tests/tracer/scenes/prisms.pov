// Linear prisms, swept along y and conically, with holes (overlapping outlines), open, turned
// and cut; on a checkered floor, flat-lit (emission only, no lights): silhouettes and hit
// points (through the patterns) are compared.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -11> look_at <0, 1, 0> angle 55 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
#declare Bands = pigment { gradient y colour_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.9>] }
                           scale 0.7 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.25 } finish { Flat } }
prism { 0, 2, 6, <-1, -1>, <1, -1>, <1.3, 0.4>, <0, 1.2>, <-1.2, 0.5>, <-1, -1>
  pigment { Bands } finish { Flat } translate <-4.5, 0, 2> }
prism { linear_sweep linear_spline 0.2, 1.6, 10,
  <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>, <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>,
  <-0.5, 0.5>, <-0.5, -0.5>
  pigment { checker rgb <0.2, 0.8, 0.3>, rgb <0.9, 0.9, 0.2> scale 0.3 } finish { Flat }
  rotate y*25 translate <-1.5, 0, 2> }
prism { conic_sweep linear_spline 0.3, 1, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>
  pigment { Bands } finish { Flat } rotate x*180 scale <1, 2, 1> translate <1.5, 2.1, 2> }
prism { 0, 1.5, 4, <-1, -0.8>, <1, -0.8>, <0, 1>, <-1, -0.8> open
  pigment { rgb <0.6, 0.1, 0.7> } finish { Flat } rotate x*-30 translate <4.5, 0.8, 2> }
prism { conic_sweep 0.5, 1, 4, <0, -1>, <1, 1>, <-1, 1>, <0, -1>
  pigment { radial frequency 8 colour_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.2, 0.2, 0.8>] } }
  finish { Flat } scale 1.5 translate <-3.5, 0, -1.5> }
difference {
  prism { -1, 1, 7, <-1, -1>, <1, -1>, <1.2, 0>, <1, 1>, <-1, 1>, <-1.2, 0>, <-1, -1> }
  sphere { <0, 1, -1>, 0.9 }
  pigment { checker rgb <0.1, 0.6, 0.6>, rgb <0.9, 0.8, 0.5> scale 0.35 } finish { Flat }
  rotate y*-25 translate <1.6, 1, -1.5> }
