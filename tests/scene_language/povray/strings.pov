// Strings and their functions; str() and vstr() in every padding and precision form.
#version 3.7;
#macro S(Label, T) #debug concat(Label, " [", T, "]\n") #end
#declare Vals = array[8] {0, 1, -1, 123.456, -0.0625, 1e-7, 98765.4321, 2.5}
#for (I, 0, 7)
  #for (W, -10, 10, 5)
    #for (P, -1, 4)
      S(concat("str ", str(I, 0, 0), " ", str(W, 0, 0), " ", str(P, 0, 0)), str(Vals[I], W, P))
    #end
  #end
#end
S("vstr1", vstr(2, <1, 2>, ", ", 0, 1))
S("vstr2", vstr(5, <1, 2, 3, 4, 5>, ", ", 0, 1))
S("vstr3", vstr(1, 1, ", ", 0, 1))
S("vstr4", vstr(7, 1, ",", 0, 1))
S("vstr5", vstr(3, <1, 2>, "|", 6, 2))
S("vstr6", vstr(5, <1, 2, 3>, ";", -6, 0))
S("vstr7", vstr(4, <1.5, -2.5, 3.5, -4.5>, " ", 0, -1))
S("concat", concat("a", "b", "cd", str(5, 0, 0)))
S("chr", concat(chr(65), chr(66), chr(48), chr(32), chr(126)))
S("substr1", substr("ABCDEFGHI", 4, 2))
S("substr2", substr("ABCDEFGHI", 1, 9))
S("substr3", substr("ABCDEFGHI", 9, 1))
S("upper", strupr("Hello, World 42!"))
S("lower", strlwr("Hello, World 42!"))
#debug concat("asc ", str(asc("A"), 0, 0), " ", str(asc("abc"), 0, 0), " ", str(asc("~"), 0, 0), "\n")
#debug concat("strlen ", str(strlen(""), 0, 0), " ", str(strlen("abc"), 0, 0), " ", str(strlen("a\nb"), 0, 0), "\n")
#debug concat("strcmp ", str(strcmp("ABC", "ABD"), 0, 0), " ", str(strcmp("b", "a"), 0, 0), " ", str(strcmp("x", "x"), 0, 0), "\n")
#debug concat("rel ", str(("a" < "b"), 0, 0), str(("a" = "a"), 0, 0), str(("b" <= "a"), 0, 0), str(("ab" > "a"), 0, 0), str(("x" != "y"), 0, 0), "\n")
#declare Name = "scene";
#declare Name = concat(Name, "_", str(3, -3, 0), ".png");
S("build", Name)
S("escapes", "tab\tq\"uote\\back")
S("unicode", "\u0041\u0062")
S("dt0", datetime(0))
S("dt1", datetime(365.25, "%Y/%m/%d %H:%M"))
S("dt2", datetime(9000.5, "%d.%m.%Y %H:%M:%S"))
#include "strings.inc"
S("Str", Str(1.25))
S("VStr", VStr(<1, 2, 3>))
S("VStr2D", VStr2D(<1, 2>))
S("Vstr", Vstr(<1.5, 2.25, 3>, 0, 2))
S("Vstr2D", Vstr2D(<1.5, 2.25>, 4, 1))
S("CRGBStr", CRGBStr(rgb <0.5, 0.25, 1>, 0, 3))
S("CRGBFTStr", CRGBFTStr(rgbft <0.5, 0.25, 1, 0.1, 0.2>, 0, 3))
#declare Tri = Triangle_Str(<0, 0, 0>, <1, 0, 0>, <0, 1, 0>);
S("Tri1", substr(Tri, 1, 40))
S("Tri2", substr(Tri, 41, strlen(Tri) - 40))
