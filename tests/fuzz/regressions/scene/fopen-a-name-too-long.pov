// #fopen, #wroats ,<xk, and App
#fopen Again "fiendlei@round fog over flat-lit tiles, a floor and the  camera looks down onto the floor and up into the sky, through the fog's layer and above it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -8> look_at <0, 1.2, 0> angle 70 }
background { rgb <0.3, 0.5, 0.9> }
fog { fog_type 2 fog_offset 0.4 fog_alt 1.3 distance 6 colour rgbft <0.8, 0.75, 0.6, 0.3, 0.15> }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.8>, rgb <0.2, 0.3, 0.2> } finish { Flat } }
box { <-4, 0, 2>, <-2, 3, 4> pigment { ro_data.txt" read
#dec
#declare Nre N = #fopen, #ge
