// Deterministic pigment patterns on flat-lit boxes and a floor (emission only, no lights):
// what a pixel shows is the pigment's colour where its centre ray meets the surface.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 12, -4> look_at <0, 0, 0.5> angle 60 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
#declare Warm = colour_map { [0 rgb <0.9, 0.2, 0.1>] [0.5 rgb <0.2, 0.8, 0.3>] [1 rgb <0.1, 0.3, 0.9>] }
plane { y, 0 pigment { checker rgb <0.8, 0.8, 0.7>, rgb <0.15, 0.2, 0.3> scale 0.7 rotate y*20 } finish { Flat } }
#macro Tile(X, Z, P)
  box { <-1.4, 0, -1.4>, <1.4, 0.5, 1.4> pigment { P } finish { Flat } translate <X, 0, Z> }
#end
Tile(-4.5,  3.5, pigment { gradient x colour_map { Warm } scale 0.8 })
Tile(-1.5,  3.5, pigment { radial frequency 6 colour_map { Warm } })
Tile( 1.5,  3.5, pigment { brick rgb <0.9, 0.9, 0.9>, rgb <0.7, 0.2, 0.1> scale 0.15 })
Tile( 4.5,  3.5, pigment { hexagon rgb 1, rgb <0.2, 0.5, 0.9>, rgb <0.9, 0.6, 0.1> scale 0.3 })
Tile(-4.5,  0.0, pigment { onion colour_map { Warm } scale 0.6 translate <0.3, 0, 0.2> })
Tile(-1.5,  0.0, pigment { wood colour_map { Warm } scale 0.3 rotate x*90 })
Tile( 1.5,  0.0, pigment { spherical colour_map { Warm } scale 1.3 })
Tile( 4.5,  0.0, pigment { square rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1>, rgb 1 scale 0.4 })
Tile(-4.5, -3.0, pigment { marble colour_map { Warm } scale 0.9 rotate y*30 })
Tile(-1.5, -3.0, pigment { triangular rgb 0.1, rgb 0.4, rgb 0.7, rgb 1, rgb <1, 0, 1>, rgb <0, 1, 1> scale 0.35 })
Tile( 1.5, -3.0, pigment { cylindrical colour_map { Warm } scale 1.2 rotate y*35 })
Tile( 4.5, -3.0, pigment { leopard colour_map { Warm } scale 0.2 })
