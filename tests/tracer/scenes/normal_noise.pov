// Noise normal patterns on tiles lit by one distant light (no shadows), for their statistics:
// the light lies in the y-z plane, so a pixel shows the pigment times the cosine between the
// tilted normal and it. Seen from above with z up, +x is on the image's left.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 20, 0> look_at <0, 0, 0> right 24 * x up 16 * z sky z }
light_source { <0, 1, -1> * 1e6 colour rgb 1 }
#declare Lit = finish { ambient 0 diffuse 1 }
#macro Tile(X, Z, N)
  box { <-3.9, -1, -3.9>, <3.9, 0, 3.9> pigment { rgb 1 } finish { Lit }
        normal { N } translate <X, 0, Z> }
#end
Tile( 8,  4, normal { bumps 0.8 scale 0.15 })
Tile( 0,  4, normal { dents 1 scale 0.2 })
Tile(-8,  4, normal { wrinkles 0.6 scale 0.2 })
Tile( 8, -4, normal { granite 0.3 scale 0.6 })
Tile( 0, -4, normal { bozo 2 scale 0.15 })
Tile(-8, -4, normal { crackle 1 scale 0.15 })
