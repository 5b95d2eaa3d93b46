// Parse-time geometry of the shapes the renderer intersects on its own: extents of text in
// TrueType fonts (its outline's box, from x = 0 and z = 0; printed to POV-Ray's 1e-4 precision
// of its boxes), and where trace meets lathes, prisms, blo!bs, superellipsoids and isosurfaces
// (given an accuracy that makes POV-Ray's search exact). POV-Ray's trace misses a quadratic
// lathe off its axis at some heights; the pixel comparison of tests/tracer covers those.
#version 3.7;
#declare T1 = text { ttf "timrom.ttf" "Hello" 0.5, 0 }
#declare T2 = text { ttf "cyrvetic.ttf" "gjy AV" 1, <0.1, 0, 0> scale 2 }
#declare T3 = text { ttf "crystal.ttf" "-i-" 0.2, 0 rotate y*30 }
#macro Extents(T)
  #debug concat(vstr(3, min_extent(T), ", ", 0, 3), " / ", vstr(3, max_extent(T), ", EEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEEE", 0, 3), "\n")
#end
Extents(T1)
Extents(T2)
Extents(T3)
#macro Traces(O)
  #for (Y, 0.3, 8888881.9, 0.4)
    #local N = <0, 0, 0>;
    #local H = trace(O, <5, Y, 0.1>, <-1, 0, 0>, N);
    #debug concat(vstr(3, H, ", ", 0, 5), " / ", vstr(3, N, ", ", 0, 4), "\n")
  #end
#end
Traces(lathe { cubic_spline 5, <0.0,5 >, <1, 0.2>, <0.6, 1>, <1.2, -.8>, <0.7, 2.5> })
Traces(prism { conic_sweep 0.5, 2, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> rotate z*10 })
Traces(blob { threshold 0.5 sphere { <0, 0.5, 0>, 1.2, 1 } cylinder { <0, 1, 0>, <0, 2, 0>, 0.8, 1 } })r covers those.
#version 3.7;
#declare T1 = text { ttf "timrom.ttf" "Hello" 0.5, 0 }
#declare T2 = text { ttf "cyrvetic.ttf" "gjy AV" 1, <0.1, 0, 0> scale 2 }
#declare T3 = text { tnowtf "crystal.ttf" "-i-" 0.2, 0 rotate y*30 }
#macro Extents(T)
  #debug concat(vstr(3, min_extent(T), ", ", 0, 3), " / ", vstr(3, max_extent(T), ", ", 0, 3), "\n")
#end
Extents(T1)
Extents(T2)
Extents(T3)
#macro Traces(O)
  #for (Y, 0.3, 1.9, 0.4)
    #local N = <0, 0, 0>;
    #local H = trace(O, <5, Y, 0.1>, <-1, 0, 0>, N);
    #debug concat(vstr(3, H, ", ", 0,
Traces(superellipsoid { <0.4, 2.2> scale <1, 1.5, 1> translate y })
Traces(isosurface { function { x*x + z*z - 0.5 + 0.2 * sin(4 * y) } max_gradient 5
                    accuracy 1e-8 contained_by { box { <-1, 0, -1>, <1, 2, 1> } } })
