// Deterministic normal patterns on tiles lit by one distant light (no shadows): what a pixel
// shows is the pigment times the cosine between the tilted normal and the light.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 12, -4> look_at <0, 0, 0.5> angle 60 }
light_source { <-3, 8, -2> * 1e5 colour rgb 1 }
#declare Lit = finish { ambient 0 diffuse 1 }
plane { y, 0 pigment { rgb <0.6, 0.6, 0.55> } finish { Lit } }
#macro Tile(X, Z, N)
  box { <-1.4, 0, -1.4>, <1.4, 0.5, 1.4> pigment { rgb <0.9, 0.85, 0.8> } finish { Lit }
        normal { N } no_shadow translate <X, 0, Z> }
#end
Tile(-4.5,  3.5, normal { gradient x 0.6 })
Tile(-1.5,  3.5, normal { gradient <1, 0, 1> 1 sine_wave scale 0.7 })
Tile( 1.5,  3.5, normal { radial 0.5 frequency 6 sine_wave })
Tile( 4.5,  3.5, normal { leopard 1.5 scale 0.2 })
Tile(-4.5,  0.0, normal { onion 0.7 triangle_wave scale 0.8 translate <0.3, 0, 0.2> })
Tile(-1.5,  0.0, normal { wood 0.5 scale 0.4 rotate x*90 })
Tile( 1.5,  0.0, normal { spherical 1.2 scale 1.3 })
Tile( 4.5,  0.0, normal { gradient z 0.8 scale <1, 1, 0.5> })
Tile(-4.5, -3.0, normal { marble 0.8 scale 0.9 rotate y*30 })
Tile(-1.5, -3.0, normal { gradient x 0.4 scale 0.5 no_bump_scale })
Tile( 1.5, -3.0, normal { gradient x 0.7 triangle_wave rotate y*30 scale 0.6 })
Tile( 4.5, -3.0, normal { cylindrical 1 scale 1.2 rotate y*35 })
