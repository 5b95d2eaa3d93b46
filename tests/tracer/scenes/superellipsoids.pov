// Superellipsoids from rounded boxes to pinched stars, turned and scaled, alone and in CSG, on
// a checkered floor, flat-lit (emission only, no lights): silhouettes and hit points (through
// the patterns) are compared.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -11> look_at <0, 1, 0> angle 55 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
#declare Bands = pigment { gradient y colour_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.9>] }
                           scale 0.7 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.25 } finish { Flat } }
superellipsoid { <1, 1> pigment { Bands } finish { Flat } translate <-4.5, 1, 2> }
superellipsoid { <0.2, 0.2> pigment { checker rgb <0.2, 0.8, 0.3>, rgb <0.9, 0.9, 0.2> scale 0.4 }
  finish { Flat } rotate <20, 35, 0> translate <-1.5, 1.2, 2> }
superellipsoid { <2, 2> pigment { Bands } finish { Flat } scale 1.2 rotate x*20 translate <1.5, 1.2, 2> }
superellipsoid { <2.5, 2.5> pigment { rgb <0.6, 0.1, 0.7> } finish { Flat } scale 1.3
  translate <4.5, 1.3, 2> }
superellipsoid { <0.5, 3> pigment { Bands } finish { Flat } scale <1.2, 0.8, 1> rotate y*30
  translate <-4, 0.8, -1.5> }
superellipsoid { <3, 0.4> pigment { radial frequency 8 colour_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.2, 0.2, 0.8>] } }
  finish { Flat } rotate x*90 translate <-1.2, 1, -1.5> }
difference {
  superellipsoid { <0.3, 0.3> }
  sphere { <0, 0, -1>, 0.9 }
  pigment { checker rgb <0.1, 0.6, 0.6>, rgb <0.9, 0.8, 0.5> scale 0.3 } finish { Flat }
  rotate y*-25 translate <1.6, 1, -1.5> }
intersection {
  superellipsoid { <1, 0.1> }
  plane { <1, 1, 0>, 0.5 }
  pigment { rgb <0.9, 0.5, 0.6> } finish { Flat } scale 1.1 translate <4.3, 1.1, -1.5> }
