// A real measured LED behind a glass dome: OSRAM's LERTDUW S2WP blue chip (its 100 000-ray
// TM-25 file from ../shared/data/rayfiles, 1.68 W, 54.6 lm) on a white floor, under a
// hemispherical glass shell, with a receiver on the floor recording lux. A start for your own
// scenes: replace the ray file, the dome or the receiver.
// Render (the folder of the ray file goes on the include path):
//   raytrace examples/osram_dome.pov +L../shared/data/rayfiles +W640 +H480 --time 60 -o out/osram_dome.exr
// Units: millimetres. The LED's chip sits at the origin and emits upward (+y).
#version 3.7;

global_settings {
    length_unit "mm"
    integrator "bidirectional"
}

camera {
    location <0, 45, -90>
    look_at <0, 4, 0>
    angle 35
}

// Floor and a back wall, white.
#declare Paint = texture { pigment { rgb 0.8 } finish { diffuse 1 ambient 0 } }
plane { y, 0 texture { Paint } }
plane { -z, -60 texture { Paint } }

// The dome: a glass shell 1 mm thick, outer radius 12 mm, centred on the chip; the floor
// hides its lower half. Each surface carries the relative index of refraction of what lies
// inside it against what lies outside: glass in air (1.5) for the outer sphere, air in glass
// (1 / 1.5) for the inner one, so a ray crossing the shell refracts twice and leaves parallel.
#declare Glass = texture { pigment { rgbt 1 } finish { ambient 0 diffuse 0 } }
sphere { <0, 0, 0>, 12 texture { Glass } interior { ior 1.5 } }
sphere { <0, 0, 0>, 11 texture { Glass } interior { ior 1 / 1.5 } }

// The LED: the file's chip faces +z; rotate x by -90 turns it to +y. Its origins reach
// z = -1.15 mm (the package below the chip): lifted 1.2 mm, all of it stays above the floor.
ray_source { "rayfile_LERTDUW_S2WP_blue_100k_20161013_IES_TM25.TM25RAY" rotate <-90, 0, 0> translate <0, 1.2, 0> }

// Illuminance on the floor around the dome, 100 x 100 mm in 50 x 50 cells (writes
// OUT.floor.exr and OUT.floor.csv in lux).
illuminance_receiver { <-50, 0.01, -50>, <0, 0, 100>, <100, 0, 0> resolution <50, 50> name "floor" }
