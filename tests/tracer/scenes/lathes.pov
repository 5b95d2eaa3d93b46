// Lathes of linear, quadratic, cubic and Bezier splines, turned and scaled, one in CSG; on a
// checkered floor, flat-lit (emission only, no lights): silhouettes and hit points (through
// the patterns) are compared.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -11> look_at <0, 1, 0> angle 55 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
#declare Bands = pigment { gradient y colour_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.9>] }
                           scale 0.7 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.25 } finish { Flat } }
lathe { linear_spline 6, <0, 0>, <1, 0>, <0.6, 0.8>, <1.1, 1.6>, <0.4, 2.3>, <0, 2.3>
  pigment { Bands } finish { Flat } translate <-4.5, 0, 2> }
lathe { quadratic_spline 6, <0.2, -0.3>, <0.9, 0>, <0.5, 0.7>, <1, 1.4>, <0.3, 2>, <0, 2.2>
  pigment { checker rgb <0.2, 0.8, 0.3>, rgb <0.9, 0.9, 0.2> scale 0.3 } finish { Flat }
  rotate z*15 translate <-1.5, 0.2, 2> }
lathe { cubic_spline 7, <0.5, -0.5>, <0.001, 0>, <0.9, 0.3>, <0.5, 1>, <1, 1.7>, <0.001, 2.2>,
  <0.5, 2.5> pigment { Bands } finish { Flat } translate <1.5, 0, 2> }
lathe { bezier_spline 8, <0, 0>, <1.5, 0>, <0, 1>, <1, 1.2>, <1, 1.2>, <1.3, 1.6>, <0.6, 2>, <0, 2>
  pigment { rgb <0.6, 0.1, 0.7> } finish { Flat } translate <4.5, 0, 2> }
lathe { cubic_spline 6, <1, -0.2>, <0.8, 0>, <1.2, 0.5>, <0.5, 1>, <0.9, 1.5>, <1, 2>
  pigment { radial frequency 8 colour_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.2, 0.2, 0.8>] } }
  finish { Flat } rotate x*-70 translate <-3.5, 1.1, -1.5> }
difference {
  lathe { linear_spline 5, <0, -1>, <1.2, -1>, <1.2, 1>, <0, 1>, <0, -1> }
  sphere { <0, 1, -1>, 0.9 }
  pigment { checker rgb <0.1, 0.6, 0.6>, rgb <0.9, 0.8, 0.5> scale 0.35 } finish { Flat }
  rotate y*-25 translate <1.6, 1, -1.5> }
