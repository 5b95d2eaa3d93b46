// Parametric surfaces: a torus of u and v turned on its side, a twisted ribbon scaled
// unevenly, a rippled sheet cut round by its sphere container, a plane patch bent into a
// saddle and cut by its box, turned; on a checkered floor, flat-lit (emission only, no
// lights): silhouettes and hit points (through the patterns) are compared. POV-Ray's hits
// stray from the surface by about its accuracy (measured with trace: 2e-3 at the default
// 0.001), which the gradients and pattern edges show: accuracy 0.0001 here. max_gradient 2 is
// above the functions' partial derivatives (at most 1.35).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.8, 0> angle 50 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.25 } finish { Flat } }
#declare Torus = parametric {
  function { (1 + 0.35*cos(v))*cos(u) }
  function { 0.35*sin(v) }
  function { (1 + 0.35*cos(v))*sin(u) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { box { <-1.4, -0.4, -1.4>, <1.4, 0.4, 1.4> } }
  max_gradient 2 accuracy 0.0001 precompute 15 x, y, z }
object { Torus pigment { checker rgb <1, 0.4, 0.2>, rgb <0.2, 0.4, 1> scale 0.25 } finish { Flat }
  rotate x*70 translate <-2.6, 1.4, 0.5> }
parametric {
  function { u*cos(2*v) } function { v } function { u*sin(2*v) }
  <-0.5, -1>, <0.5, 1>
  contained_by { box { <-0.6, -1.1, -0.6>, <0.6, 1.1, 0.6> } }
  max_gradient 2 accuracy 0.0001 precompute 15 x, y, z
  pigment { gradient y scale 0.5
            colour_map { [0 rgb <0.9, 0.9, 0.2>] [0.5 rgb <0.2, 0.8, 0.3>] [1 rgb <0.9, 0.9, 0.2>] } }
  finish { Flat } scale <1.6, 1, 1> rotate y*20 translate <0, 1.1, 0> }
parametric {
  function { u } function { 0.3*sin(3*u)*cos(2*v) } function { v }
  <-1.5, -1.5>, <1.5, 1.5>
  contained_by { sphere { 0, 1.2 } }
  max_gradient 2 accuracy 0.0001 precompute 15 x, y, z
  pigment { radial frequency 8 colour_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.3, 0.2, 0.8>] } }
  finish { Flat } rotate x*-20 translate <2.5, 1.2, 0> }
parametric {
  function { u } function { 0.5*u*v } function { v }
  <-1.5, -1.5>, <1.5, 1.5>
  contained_by { box { <-1, -1, -1>, <1, 1, 1> } }
  max_gradient 2 accuracy 0.0001 precompute 15 x, y, z
  pigment { checker rgb <0.9, 0.2, 0.6>, rgb <0.9, 0.9, 0.9> scale 0.3
            translate <0.1, 0.05, 0.1> }
  finish { Flat } rotate <-45, 25, 0> translate <0.3, 1, -2.6> }
