// Bump maps on thin tiles lit by one distant light (no shadows): what a pixel shows is the
// pigment times the cosine between the tilted normal and the light. The images lie in the
// tiles' plane (on surfaces oblique to the projection POV-Ray tilts otherwise). The images are
// written beside this scene by render_images_test.cpp (colours.png: 8 x 6 sRGB colours;
// grey.pgm: 5 x 4 grey).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 12, -4> look_at <0, 0, 0.5> angle 60 }
light_source { <-3, 8, -2> * 1e5 colour rgb 1 }
#declare Lit = finish { ambient 0 diffuse 1 }
plane { y, 0 pigment { rgb <0.6, 0.6, 0.55> } finish { Lit } }
#macro Tile(X, Z, N)
  box { <-1.4, 0, -1.4>, <1.4, 0.02, 1.4> pigment { rgb <0.9, 0.85, 0.8> } finish { Lit }
        normal { N } no_shadow translate <X, 0, Z> }
#end
Tile(-4.5, 3.5, normal { bump_map { png "colours.png" bump_size 3 } rotate x*90 scale 2.5
                         translate <-1.2, 0, -1.2> })
Tile(-1.5, 3.5, normal { bump_map { pgm "grey.pgm" bump_size 2 } rotate x*90 scale <2, 1, 1.5> })
Tile( 1.5, 3.5, normal { bump_map { pgm "grey.pgm" bump_size 1.5 interpolate 2 } rotate x*90
                         rotate y*30 scale 2 })
Tile( 4.5, 3.5, normal { bump_map { png "colours.png" bump_size 4 } rotate x*90 scale 2
                         translate <-1, 0, -1> })
Tile(-4.5, 0.0, normal { bump_map { pgm "grey.pgm" bump_size 4 interpolate 4 } rotate x*90
                         scale 2.4 })
Tile(-1.5, 0.0, normal { bump_map { png "colours.png" bump_size 2 interpolate 2 } rotate x*90
                         rotate y*-45 scale 3 })
Tile( 1.5, 0.0, normal { bump_map { pgm "grey.pgm" bump_size 6 } rotate x*90 scale 0.9 })
Tile( 4.5, 0.0, normal { bump_map { png "colours.png" bump_size 3 } rotate x*90 rotate y*60
                         scale 2 })
