// Parse-time extents of text in TrueType fonts (its outline's box, from x = 0 and z = 0),
// scaled, offset and turned; printed to POV-Ray's own precision of its boxes (1e-4).
#version 3.7;
#declare T1 = text { ttf "timrom.ttf" "Hello" 0.5, 0 }
#declare T2 = text { ttf "cyrvetic.ttf" "gjy AV" 1, <0.1, 0, 0> scale 2 }
#declare T3 = text { ttf "crystal.ttf" "-i-" 0.2, 0 rotate y*30 }
#macro Extents(T)
  #debug concat(vstr(3, min_extent(T), ", ", 0, 3), " / ", vstr(3, max_extent(T), ", ", 0, 3), "\n")
#end
Extents(T1)
Extents(T2)
Extents(T3)
