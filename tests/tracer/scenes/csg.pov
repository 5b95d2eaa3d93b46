// CSG, clipped_by and inverse on flat-lit solids over a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -11> look_at <0, 1, 0> angle 55 }
#declare Flat = finish { ambient 0 diffuse 0 emission 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.25 } finish { Flat } }
difference {
  box { <-1, 0, -1>, <1, 2, 1> }
  sphere { <0, 2, 0>, 1.2 }
  cylinder { <-2, 0.8, 0>, <2, 0.8, 0>, 0.4 }
  pigment { gradient y colour_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.9>] } scale 2 }
  finish { Flat }
  rotate y*30 translate <-4, 0, 1.5>
}
intersection {
  sphere { 0, 1.3 }
  box { -1, 1 }
  cylinder { -2*x, 2*x, 0.7 inverse }
  pigment { checker rgb <0.2, 0.8, 0.3>, rgb <0.9, 0.9, 0.2> scale 0.3 } finish { Flat }
  rotate <20, 40, 0> translate <-0.8, 1.4, 2>
}
merge {
  cylinder { <0, 0, 0>, <0, 2.4, 0>, 0.5 }
  cone { <0, 1.2, 0>, 1.1, <0, 2.6, 0>, 0 }
  torus { 0.8, 0.25 translate 0.5*y }
  pigment { radial frequency 8 colour_map { [0 rgb <1, 0.5, 0>] [1 rgb <0.2, 0.2, 0.8>] } }
  finish { Flat } translate <2.4, 0, 1.5>
}
sphere { <4.6, 1.2, 0>, 1.2
  clipped_by { plane { y, 1.5 } }
  clipped_by { box { <3, 0, -0.6>, <6, 3, 3> } }
  pigment { onion colour_map { [0 rgb <0.1, 0.6, 0.6>] [1 rgb <0.9, 0.8, 0.5>] } scale 0.4 }
  finish { Flat } }
intersection {
  plane { y, 1.8 } plane { -y, 0 } plane { x, 1 } plane { -x, 1 } plane { z, 0.6 } plane { -z, 0.6 }
  pigment { rgb <0.6, 0.1, 0.7> } finish { Flat } rotate y*25 translate <1, 0, -2.6>
}
union {
  sphere { <-1, 0, 0>, 0.6 } sphere { <1, 0, 0>, 0.6 }
  pigment { rgb <0.2, 0.9, 0.9> } finish { Flat } clipped_by { plane { z, 0.2 } }
  translate <-3, 0.7, -2.5>
}
// bounded_by: POV-Ray drops it on objects it can bound itself (the sphere below shows whole);
// an unbounded one (the plane) is tested only along rays that meet its bound.
intersection {
  sphere { 0, 1 } sphere { 0, 0.6 inverse } plane { -z, 0 }
  pigment { rgb <0.9, 0.6, 0.2> } finish { Flat }
  bounded_by { sphere { 0, 1.001 } }
  rotate y*-30 translate <-1.2, 0.8, -5>
}
sphere { <3.6, 0.8, -3.6>, 0.8
  bounded_by { box { <3.2, 0, -4.5>, <4.4, 1.2, -2.5> } }
  pigment { rgb <0.3, 0.5, 1> } finish { Flat } }
plane { z, -6 bounded_by { box { <0.8, 0.2, -6.1>, <2.2, 1.4, -5.9> } }
  pigment { rgb <1, 0.2, 0.6> } finish { Flat } }
// Parts with textures of their own: each shows its own where its surface is the solid's (the
// cut of the subtracted cylinder shows the cylinder's pigment).
difference {
  box { <-0.8, 0, -0.8>, <0.8, 1.2, 0.8> pigment { rgb <0.95, 0.85, 0.3> } finish { Flat } }
  cylinder { <0, 0.6, -2>, <0, 0.6, 2>, 0.45 pigment { rgb <0.2, 0.4, 0.95> } finish { Flat } }
  rotate y*-20 translate <4.2, 0, -1.4>
}
