// Julia fractals: quaternion squares and cubes, hypercomplex squares and a hypercomplex
// function, turned and scaled, one cut by a box, one sliced at w = 0.2; on a checkered floor,
// flat-lit (emission only, no lights): silhouettes and hit points (through the patterns) are
// compared.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -11> look_at <0, 1, 0> angle 55 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
#declare Bands = pigment { gradient y colour_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.9>] }
                           scale 0.7 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.25 } finish { Flat } }
julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 20
  pigment { Bands } finish { Flat } scale 1.3 translate <-4, 1.3, 2> }
julia_fractal { <-0.03, 0.5, -0.2, -0.5> quaternion cube max_iteration 8 precision 20
  pigment { checker rgb <0.2, 0.8, 0.3>, rgb <0.9, 0.9, 0.2> scale 0.3 } finish { Flat }
  rotate <30, 20, 0> scale 1.2 translate <-0.5, 1.3, 2> }
julia_fractal { <0.2, 0.1, 0.59, -0.2> hypercomplex sqr max_iteration 7 precision 20
  pigment { Bands } finish { Flat } scale 1.3 translate <3.5, 1.3, 2> }
julia_fractal { <-0.745, 0, 0.113, 0.05> hypercomplex max_iteration 9 precision 20
  slice <0, 0, 0, 1>, 0.2
  pigment { radial frequency 8 colour_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.2, 0.2, 0.8>] } }
  finish { Flat } scale <1, 2, 1> rotate <135, -30, 0> translate <-3, 1.5, -1.5> }
intersection {
  julia_fractal { <0.33, 0.54, 0.52, 0.32> quaternion cube max_iteration 7 precision 20 }
  box { <-2, -2, -2>, <2, 2, 0.2> }
  pigment { rgb <0.6, 0.1, 0.7> } finish { Flat } scale 1.5 translate <1.5, 1.2, -1.5> }
