// Isosurfaces of functions of the language (expressions, internal functions), in box and
// sphere containers, capped and open, turned and cut; on a checkered floor, flat-lit (emission
// only, no lights): silhouettes and hit points (through the patterns) are compared.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
camera { location <0, 7, -11> look_at <0, 1, 0> angle 55 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
#declare Bands = pigment { gradient y colour_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.9>] }
                           scale 0.7 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.25 } finish { Flat } }
isosurface { function { x*x + y*y + z*z - 1 } max_gradient 4 contained_by { box { -2, 2 } }
  pigment { Bands } finish { Flat } translate <-4.5, 1, 2> }
isosurface { function { f_torus(x, y, z, 0.9, 0.35) } max_gradient 2
  contained_by { box { <-1.3, -0.4, -1.3>, <1.3, 0.4, 1.3> } }
  pigment { checker rgb <0.2, 0.8, 0.3>, rgb <0.9, 0.9, 0.2> scale 0.3 } finish { Flat }
  rotate x*60 translate <-1.5, 1.3, 2> }
isosurface { function { sqrt(x*x + z*z) - 0.8 + 0.15 * sin(6 * y) } threshold 0
  contained_by { box { <-1, 0, -1>, <1, 2, 1> } } pigment { Bands } finish { Flat }
  translate <1.5, 0, 2> }
isosurface { function { sqrt(x*x + z*z) - 0.8 } contained_by { box { <-1, 0, -1>, <1, 2, 1> } }
  open pigment { rgb <0.6, 0.1, 0.7> } finish { Flat } rotate z*20 translate <4.5, 0, 2> }
isosurface { function { abs(x) + abs(y) + abs(z) - 1.2 } contained_by { sphere { 0, 1 } }
  pigment { Bands } finish { Flat } translate <-4, 1, -1.5> }
isosurface { function { y - 0.4 * sin(3 * x) * cos(3 * z) } threshold 0.1 max_gradient 2.5
  contained_by { box { -1, 1 } }
  pigment { radial frequency 8 colour_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.2, 0.2, 0.8>] } }
  finish { Flat } translate <-1.2, 1, -1.5> }
difference {
  isosurface { function { max(abs(x), abs(y), abs(z)) - 0.85 } contained_by { box { -1, 1 } } }
  sphere { <0, 0, -1>, 0.8 }
  pigment { checker rgb <0.1, 0.6, 0.6>, rgb <0.9, 0.8, 0.5> scale 0.3 } finish { Flat }
  rotate y*-25 translate <1.6, 1, -1.5> }
