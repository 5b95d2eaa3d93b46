// Layered textures, texture maps and texture lists on flat-lit tiles (emission only, no
// lights): what a pixel shows is the layers' colours composed as POV-Ray composes them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 12, -4> look_at <0, 0, 0.5> angle 60 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
plane { y, 0 texture { pigment { rgb <0.8, 0.8, 0.7> } finish { Flat } }
                texture { pigment { checker rgbt <0.1, 0.2, 0.6, 0.3>, rgbf <1, 1, 1, 1> scale 0.7 } finish { Flat } } }
#declare BlueUnderRed = texture { pigment { rgb <0, 0, 1> } finish { Flat } }
                       texture { pigment { rgbt <1, 0, 0, 0.5> } finish { Flat } }
#declare Tile = box { <-1.4, 0, -1.4>, <1.4, 0.5, 1.4> }
object { Tile texture { pigment { rgb <1, 0, 0> } finish { Flat } } texture { pigment { rgbt <0, 0, 1, 0.25> } finish { Flat } } translate <-4.5, 0, 3.5> }
object { Tile texture { pigment { rgb <1, 1, 0> } finish { Flat } } texture { pigment { rgbf <0, 1, 1, 0.5> } finish { Flat } } translate <-1.5, 0, 3.5> }
object { Tile texture { pigment { rgb <0.2, 0.9, 0.3> } finish { Flat } }
                texture { pigment { gradient x colour_map { [0 rgbt <1, 0, 0, 1>] [1 rgbft <0.2, 0.3, 1, 0.4, 0.2>] } scale 0.8 } finish { Flat } } translate <1.5, 0, 3.5> }
object { Tile texture { gradient x texture_map { [0.2 pigment { rgb <0.9, 0.2, 0.1> } finish { Flat }]
                                                  [0.8 pigment { rgb <0.1, 0.3, 0.9> } finish { Flat }] } scale 1.2 } translate <4.5, 0, 3.5> }
object { Tile texture { checker texture { pigment { rgb 1 } finish { Flat } } texture { pigment { rgb <0.3, 0.1, 0.6> } finish { Flat } } scale 0.45 } translate <-4.5, 0, 0.0> }
object { Tile texture { hexagon texture { pigment { rgb 1 } finish { Flat } }
                                  texture { pigment { rgb <0.9, 0.6, 0.1> } finish { Flat } }
                                  texture { pigment { rgb <0.1, 0.6, 0.2> } finish { Flat } } scale 0.3 } translate <-1.5, 0, 0.0> }
object { Tile texture { radial frequency 4 texture_map { [0 pigment { rgb <1, 1, 1> } finish { Flat }]
                                              [1 BlueUnderRed] } } translate <1.5, 0, 0.0> }
object { Tile texture { pigment { rgb <0.1, 0.1, 0.1> } finish { Flat } }
                texture { pigment { rgbt <0.9, 0.9, 0.2, 0.6> } finish { Flat } }
                texture { pigment { brick rgbt <1, 1, 1, 1>, rgbf <0.8, 0.3, 0.2, 0.7> scale 0.15 } finish { Flat } } translate <4.5, 0, 0.0> }
