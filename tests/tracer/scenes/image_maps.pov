// Image maps on flat-lit boxes, a sphere, a cylinder and a torus (emission only, no lights):
// what a pixel shows is the image's colour where its centre ray meets the surface. The images
// are written beside this scene by render_images_test.cpp: colours.png (8 x 6, 8-bit sRGB),
// ramp.exr (4 x 3, linear floats) and grey.pgm (5 x 4, 8-bit linear).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x*16 up y*12 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
// Planar, repeated, scaled unevenly.
box { <-7.5, 0.7, 0>, <-2.5, 5.5, 1>
      pigment { image_map { png "colours.png" } scale <2, 1.5, 1> translate <-7.3, 1, 0> }
      finish { Flat } }
// Planar once: outside the image the box is clear (the black background shows).
box { <-2, 0.7, 0>, <2.5, 5.5, 1>
      pigment { image_map { png "colours.png" once } scale 3 translate <-1.7, 1.4, 0> }
      finish { Flat } }
// Bilinear over linear floats, turned.
box { <3, 0.7, 0>, <7.5, 5.5, 1>
      pigment { image_map { exr "ramp.exr" interpolate 2 } scale 3.1 rotate z*10
                translate <3.4, 1.1, 0> }
      finish { Flat } }
// Spherical, turned about y.
sphere { <-5, -3, 0>, 2.5
         pigment { image_map { png "colours.png" map_type 1 } rotate y*30 translate <-5, -3, 0> }
         finish { Flat } }
// Cylindrical, up the cylinder.
cylinder { <0, -5.5, 0>, <0, -0.5, 0>, 2
           pigment { image_map { png "colours.png" map_type 2 } scale <1, 5, 1>
                     rotate y*-20 translate <0, -5.5, 0> }
           finish { Flat } }
// Normalised distance over a linear 8-bit file.
box { <3, -5.5, 0>, <7.5, -0.7, 1>
      pigment { image_map { pgm "grey.pgm" interpolate 4 } scale 4.5 translate <3, -5.5, 0> }
      finish { Flat } }
// Toroidal (major radius 1), seen from above and a little in front.
torus { 1, 0.45 pigment { image_map { png "colours.png" map_type 5 } }
        finish { Flat } rotate x*-60 scale 1.1 translate <0.2, 4, -2> }
