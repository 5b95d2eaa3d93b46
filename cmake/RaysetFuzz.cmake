# Flags of a fuzz tree (RAYSET_FUZZ): every library is compiled with libFuzzer's coverage
# instrumentation and the sanitizers, so that the harnesses in fuzz/ see the edges of our code
# and a memory error or undefined behaviour anywhere in it stops the run. Only the harnesses
# link libFuzzer itself (fuzz/CMakeLists.txt), so the tools built beside them (rayconv, which
# makes the seed corpora) keep their own main().

if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "RAYSET_FUZZ needs clang (libFuzzer): configure with "
                      "-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang")
endif()
if(RAYSET_SANITIZE)
  message(FATAL_ERROR "RAYSET_FUZZ brings its own sanitizers: leave RAYSET_SANITIZE off")
endif()

# -fno-sanitize-recover: undefined behaviour is a finding, so it must stop the run as ASan does.
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
                    -fno-sanitize-recover=all)
add_link_options(-fsanitize=address,undefined)
set(RAYSET_FUZZ_FLAGS -fsanitize=fuzzer,address,undefined)
