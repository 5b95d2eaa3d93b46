// Height fields flat-lit (emission only, no lights), coloured by height so that each pixel
// shows where its centre ray meets the field. The images are written beside this scene by
// render_images_test.cpp: grey.pgm (5 x 4 grey levels: heights over 255) and colours.png (8 x 6
// 8-bit colours: heights from red and green as the high and low bytes of 16 bits).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 11, -9> look_at <0, 0, 0.3> angle 55 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
#declare ByHeight = pigment { gradient y colour_map { [0 rgb <0.1, 0.2, 0.9>]
                              [0.5 rgb <0.2, 0.9, 0.3>] [1 rgb <0.9, 0.3, 0.1>] } }
#declare Grey = height_field { pgm "grey.pgm" }
plane { y, -1 pigment { checker rgb 0.1, rgb 0.25 } finish { Flat } }
object { Grey scale <3, 1.5, 3> rotate y*10 translate <-6.5, 0, 1>
         pigment { ByHeight scale 1.5 } finish { Flat } }
height_field { png "colours.png" smooth scale <3, 1.2, 3> translate <-1.5, 0, 1>
               pigment { ByHeight scale 1.2 } finish { Flat } }
height_field { pgm "grey.pgm" water_level 0.35 scale <3, 1.5, 3> translate <3.2, 0, 1>
               pigment { ByHeight scale 1.5 } finish { Flat } }
intersection { object { Grey scale <3, 1.5, 3> } sphere { <1.5, 0, 1.5>, 1.6 }
               translate <-6.5, 0, -3.5> pigment { ByHeight scale 1.5 } finish { Flat } }
object { Grey scale <3, 1.5, 3> clipped_by { sphere { <1.5, 0.5, 1.5>, 1.5 } }
         translate <-1.5, 0, -3.5> pigment { ByHeight scale 1.5 } finish { Flat } }
difference { box { <0, 0, 0>, <3, 1.2, 3> } object { Grey scale <3, 1.5, 3> }
             translate <3.2, 0, -3.5> pigment { ByHeight scale 1.5 } finish { Flat } }
