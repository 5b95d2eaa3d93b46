// Blobs of sphere and cylinder components, a negative one, components moved on their own,
// thresholds, a blob in CSG; on a checkered floor, flat-lit (emission only, no lights):
// silhouettes and hit points (through the patterns) are compared.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -11> look_at <0, 1, 0> angle 55 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
#declare Bands = pigment { gradient y colour_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.9>] }
                           scale 0.7 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.25 } finish { Flat } }
blob { threshold 0.6
  sphere { <-0.5, 0, 0>, 1, 1 } sphere { <0.5, 0, 0>, 1, 1 } sphere { <0, 0.7, 0>, 0.8, 1 }
  pigment { Bands } finish { Flat } translate <-4.5, 1, 2> }
blob { threshold 0.5
  cylinder { <-0.8, 0, 0>, <0.8, 0, 0>, 0.7, 1 } sphere { <0, 0.5, 0>, 0.9, 1.5 }
  pigment { checker rgb <0.2, 0.8, 0.3>, rgb <0.9, 0.9, 0.2> scale 0.3 } finish { Flat }
  rotate y*30 translate <-1.5, 1, 2> }
blob { threshold 0.4
  sphere { 0, 1.4, 1 } sphere { <0.5, 0.5, -0.5>, 0.8, -2 }
  pigment { Bands } finish { Flat } translate <1.5, 1.1, 2> }
blob { threshold 0.3
  sphere { 0, 1, 1 scale <1.5, 0.6, 1> } sphere { 0, 1, 1 scale <0.6, 1.6, 0.6> translate 0.3*y }
  pigment { rgb <0.6, 0.1, 0.7> } finish { Flat } translate <4.5, 1, 2> }
blob { threshold 0.65
  sphere { <-0.6, 0, 0>, 1, 1 } sphere { <0.6, 0, 0>, 1, 1 } sphere { <0, 0, 0.8>, 1, 1 }
  pigment { radial frequency 8 colour_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.2, 0.2, 0.8>] } }
  finish { Flat } scale 1.2 translate <-3.5, 0.8, -1.5> }
difference {
  blob { threshold 0.5 cylinder { <0, -0.9, 0>, <0, 0.9, 0>, 1, 1 } sphere { 0, 1.4, 0.8 } }
  box { <-2, 0.05, -2>, <0.05, 2, 0.05> }
  pigment { checker rgb <0.1, 0.6, 0.6>, rgb <0.9, 0.8, 0.5> scale 0.3 } finish { Flat }
  rotate y*-25 translate <0.5, 1.1, -1.5> }
