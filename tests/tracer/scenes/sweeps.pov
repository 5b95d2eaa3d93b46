// Sphere sweeps of the three spline kinds (a bent linear arm of varied radii, a wavy b_spline
// tube, a cubic_spline loop crossing itself), turned and scaled unevenly; a cubic sweep cut
// open by a box and a box grooved by a linear and a b_spline sweep (differences); on a
// checkered floor, flat-lit (emission only, no lights): silhouettes and hit points (through
// the patterns) are compared.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -11> look_at <0, 1, 0> angle 55 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
#declare Bands = pigment { gradient y colour_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.9>] }
                           scale 0.7 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.25 } finish { Flat } }
sphere_sweep { linear_spline 5, <-1, 0, 0>, 0.5, <0, 1.5, 0>, 0.3, <1, 1, 0.5>, 0.6,
  <1.5, 2.5, 0>, 0.2, <0.5, 3, -0.5>, 0.4
  pigment { Bands } finish { Flat } rotate y*30 scale <1, 0.9, 1.2> translate <-4.2, 0.5, 2> }
sphere_sweep { b_spline 7, <-2, 0, 0>, 0.3, <-1.5, 1, 0>, 0.5, <-0.5, 0.2, 0.5>, 0.7,
  <0.5, 1.5, 0>, 0.4, <1, 0.5, -0.5>, 0.6, <2, 1, 0>, 0.3, <2.5, 0, 0>, 0.5
  pigment { checker rgb <0.2, 0.8, 0.3>, rgb <0.9, 0.9, 0.2> scale 0.3 } finish { Flat }
  rotate x*-20 scale <1.1, 1, 0.8> translate <0, 1, 4> }
sphere_sweep { cubic_spline 8, <0, 0, -1>, 0.2, <-1, 0.5, 0>, 0.3, <0, 1, 1>, 0.4, <1, 1.5, 0>, 0.25,
  <0, 2, -1>, 0.35, <-1, 1, 0>, 0.2, <0, 0.3, 1>, 0.3, <1, 0, 0>, 0.3
  pigment { radial frequency 8 colour_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.2, 0.2, 0.8>] } }
  finish { Flat } rotate y*40 scale <1.2, 1, 1> translate <4.2, 0.2, 2.5> }
difference {
  sphere_sweep { cubic_spline 6, <-2, 0, 1>, 0.4, <-1.5, 0.6, 0>, 0.5, <-0.5, 0.6, -0.5>, 0.7,
    <0.5, 0.8, 0.3>, 0.5, <1.5, 0.5, 0>, 0.6, <2, 0, -1>, 0.4 }
  box { <-3, 0.9, -3>, <3, 3, 3> }
  pigment { checker rgb <0.1, 0.6, 0.6>, rgb <0.9, 0.8, 0.5> scale 0.35 } finish { Flat }
  rotate y*-15 translate <-2.6, 0, -2.2> }
difference {
  box { <-1.2, 0, -1>, <1.2, 1.3, 1> }
  sphere_sweep { linear_spline 3, <-1.6, 1.5, -0.3>, 0.5, <0, 1, 0>, 0.3, <1.6, 1.5, 0.4>, 0.6 }
  sphere_sweep { b_spline 5, <-2, 0.6, -1.5>, 0.2, <-1, 0.5, -1>, 0.3, <0, 0.7, -1.1>, 0.4,
    <1, 0.4, -0.9>, 0.2, <2, 0.6, -1.3>, 0.3 }
  pigment { Bands } finish { Flat } rotate y*-25 translate <2.6, 0, -2.2> }
