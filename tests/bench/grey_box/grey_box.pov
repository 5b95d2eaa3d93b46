// A closed grey room for convergence against other renderers: 2 m cube, walls 0.6, a floor slab
// of 0.4 and a block of 0.6, lit by a 1 W Lambertian disk of radius 50 mm on the ceiling, given
// as its model (disk.vdb, made by ../grey_box.sh from a synthetic ray file). mitsuba_grey_box.py
// holds the same room for Mitsuba 3. Units: mm.
global_settings { integrator "path" }
camera { location <0, 1000, -950> look_at <0, 700, 0> angle 90 }
box { <-1000, 0, -1000>, <1000, 2000, 1000> pigment { rgb 0.6 } finish { diffuse 1 ambient 0 } }
box { <-999, 0, -999>, <999, 1, 999> pigment { rgb 0.4 } finish { diffuse 1 ambient 0 } }
box { <-300, 1, -200>, <100, 500, 300> pigment { rgb 0.6 } finish { diffuse 1 ambient 0 } }
ray_source { "disk.vdb" rotate <90, 0, 0> translate <0, 1999, 0> }
