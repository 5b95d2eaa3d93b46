// #fopen, #write, #read and #fclose: values written as POV-Ray writes them (%g floats, <x,y,z>
// vectors), read back, and the end of the file closing the handle.
#version 3.7;
#fopen Out "fileio_data.txt" write
#write (Out, "\"first\", ", 1/3, ", ", <1, 2.5, -3>, ",\n")
#write (Out, -1e-7, ",", 123456789, ",", <0.25, 2>, ",", "\"last\",\n")
#fclose Out
#fopen In "fileio_data.txt" read
#read (In, S1, F1, V1)
#debug concat("s1 [", S1, "]\n")
#debug concat("f1 ", str(F1, 0, 9), "\n")
#debug concat("v1 ", vstr(3, V1, ",", 0, 9), "\n")
#read (In, F2, F3, V2, S2)
#debug concat("f2 ", str(F2, 0, 12), " f3 ", str(F3, 0, 3), "\n")
#debug concat("v2 ", vstr(2, V2, ",", 0, 9), " s2 [", S2, "]\n")
#ifdef (In) #debug "open\n" #else #debug "closed at its end\n" #end
#fopen App "fileio_data.txt" append
#write (App, "7, 8\n")
#fclose App
#fopen Again "fileio_data.txt" read
#declare N = 0;
#while (defined(Again))
  #read (Again, X)
  #declare N = N + 1;
  #undef X  // items of different types: a fresh identifier for each
#end
#debug concat("items ", str(N, 0, 0), "\n")
