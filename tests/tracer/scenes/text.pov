// Text in POV-Ray's TrueType fonts on flat-lit objects (emission only, no lights): glyph
// outlines with curves and holes, kerning (AV, OV), an offset between characters, a thick
// turned text and text cut from a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <2.2, 0.3, -4.5> look_at <2.2, 0.3, 0> angle 52 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
plane { z, 2 pigment { rgb <0.15, 0.1, 0.2> } finish { Flat } }
text { ttf "timrom.ttf" "Ray Wavefg%" 0.4, 0 pigment { rgb <1, 0.8, 0.2> } finish { Flat } }
text { ttf "cyrvetic.ttf" "AVOVRay 3.7" 0.3, <0.05, 0, 0>
       pigment { rgb <0.2, 0.6, 1> } finish { Flat } translate <0, -1, 0> rotate y*20 }
text { ttf "crystal.ttf" "abc" 1, 0 pigment { rgb <0.6, 1, 0.3> } finish { Flat }
       scale 0.8 rotate x*-40 translate <-0.3, 1.2, 0.5> }
difference {
  box { <0, 0, 0>, <2.2, 1, 0.3> pigment { rgb <0.9, 0.3, 0.4> } finish { Flat } }
  text { ttf "timrom.ttf" "BO8" 1, 0 pigment { rgb <0.3, 0.2, 0.9> } finish { Flat }
         translate <0.15, 0.2, -0.5> }
  translate <2.6, 1.1, 0>
}
