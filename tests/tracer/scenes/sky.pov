// A sky_sphere of two layers over a background, turned and brightened: what camera rays that
// leave the scene see. Nothing else is in the scene.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, 0> look_at <0.3, 0.2, 1> angle 100 }
background { rgb <0.1, 0.3, 0.2> }
sky_sphere {
  pigment { gradient y colour_map { [0 rgb <0.9, 0.5, 0.2>] [0.5 rgb <0.3, 0.4, 0.9>] [1 rgb <0.1, 0.1, 0.5>] }
            translate -0.5 * y scale 2 }
  pigment { checker rgbt <1, 1, 1, 0.6>, rgbf <0.2, 0.9, 0.3, 0.5> scale 0.25 }
  pigment { radial frequency 5 colour_map { [0 rgbt 1] [0.5 rgbt 1] [0.5 rgbt <1, 0.2, 0.2, 1>] [1 rgbt <0.8, 0.1, 0.1, 0.3>] } }
  rotate <10, 25, 0>
  emission 0.8
}
