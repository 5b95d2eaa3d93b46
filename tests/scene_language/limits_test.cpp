// Hostile and runaway scenes: every limit of ParseOptions stops them with an error that names
// the limit, the place (file, line, column, include and macro chain) and how to raise it;
// none crashes, hangs or takes the machine's memory.
#include <chrono>
#include <string>

#include <gtest/gtest.h>

#include "scene_language/scene_test_support.h"
#include "support/test_support.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
namespace {

using namespace scene_test;

TEST(SceneLanguageLimits, RunawayRecursionStopsAtTheNestingLimitWithItsCallChain) {
    ParseOptions options;
    options.max_nesting = 100;
    const std::string e = error_of("#version 3.7;\n#macro R(N)\n  R(N + 1)\n#end\nR(0)\n", options);
    EXPECT_NE(e.find("nesting limit: more than 100 macro calls, include files and blocks in "
                     "progress (runaway "
                     "recursion in macro R?) (ParseOptions::max_nesting) at test.pov:3:3"),
              std::string::npos)
        << e;
    // The innermost calls and how many more, not a hundred lines of them.
    EXPECT_NE(e.find("(in macro R called at test.pov:3:3) (in macro R called at test.pov:3:3)"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("more macro calls)"), std::string::npos) << e;
    EXPECT_LT(e.size(), 800u);
}

TEST(SceneLanguageLimits, DefaultNestingLimitHoldsOnTheParserStack) {
    // 100000 nested parentheses and 50000 nested unions: errors, not a stack overflow.
    const std::string parens =
        "#declare X = " + std::string(100000, '(') + "1" + std::string(100000, ')') + ";";
    EXPECT_NE(error_of(parens).find("nesting limit: more than 1000"), std::string::npos);
    std::string unions;
    for (int i = 0; i < 50000; ++i) unions += "union { ";
    EXPECT_NE(error_of(unions).find("nesting limit: more than 1000"), std::string::npos);
    // Just under the limit is fine.
    const std::string deep =
        "#declare X = " + std::string(900, '(') + "1" + std::string(900, ')') + ";";
    EXPECT_EQ(error_of(deep), "no error");
}

TEST(SceneLanguageLimits, LoopsStopAtTheIterationLimit) {
    ParseOptions options;
    options.max_loop_iterations = 1000;
    EXPECT_EQ(error_of("#declare I = 0;\n#while (I < 10)\n  sphere { 0, 1 }\n#end\n", options),
              "loop limit: more than 1000 #while and #for iterations in total "
              "(ParseOptions::max_loop_iterations) "
              "at test.pov:2:1");
    EXPECT_EQ(error_of("#for (I, 1, 1e9)\n#end\n", options),
              "loop limit: more than 1000 #while and #for iterations in total "
              "(ParseOptions::max_loop_iterations) "
              "at test.pov:2:1");
    // The limit counts all loops together, nested ones included.
    EXPECT_EQ(error_of("#for (I, 1, 40) #for (J, 1, 24) #end #end", options), "no error");
    EXPECT_NE(error_of("#for (I, 1, 40) #for (J, 1, 25) #end #end", options).find("loop limit"),
              std::string::npos);
}

TEST(SceneLanguageLimits, MacroCallsStopAtTheirLimit) {
    // Fib(51) calls itself about 4e10 times, never deeper than 51 (found by fuzzing).
    const std::string fib =
        "#macro Fib(N) #if (N < 2) #local R = N; #else #local R = Fib(N - 1) + Fib(N - 2); "
        "#end R #end\n"
        "#declare X = Fib(NUMBER);\n";
    const auto fib_of = [&](int n) {
        std::string text = fib;
        text.replace(text.find("NUMBER"), 6, std::to_string(n));
        return text;
    };
    ParseOptions options;
    options.max_macro_calls = 1000;
    const std::string error = error_of(fib_of(51), options);
    EXPECT_EQ(error.rfind("macro limit: more than 1000 macro calls in total "
                          "(ParseOptions::max_macro_calls) at test.pov:1:58 (in macro Fib called "
                          "at test.pov:1:58)",
                          0),
              0u)
        << error;
    // Fib(14) takes 2 Fib(15) - 1 = 1219 calls, Fib(13) 753.
    EXPECT_NE(error_of(fib_of(14), options).find("macro limit"), std::string::npos);
    EXPECT_EQ(error_of(fib_of(13), options), "no error");
}

TEST(SceneLanguageLimits, FunctionLoopsStopAtTheirTermLimit) {
    // A bound of 3e84 would sum for ever (past 2^53 the variable's step of 1 no longer moves it).
    EXPECT_EQ(error_of("#declare F = function(n) { sum(k, 1, 3e84, k * k) }\n#declare X = F(1);\n"),
              "not supported: sum() or prod() of more than 1000000 terms, nested loops and called "
              "functions' loops included (this renderer's limit) at test.pov:2:14");
    // Nested loops and the loops of the functions a loop calls count together: 1001 x 1001 terms.
    EXPECT_NE(error_of("#declare G = function(n) { sum(j, 1, 1001, n * j) }\n"
                       "#declare H = function(n) { prod(i, 1, 1001, G(i) / G(i)) }\n"
                       "#declare X = H(1);\n")
                  .find("more than 1000000 terms"),
              std::string::npos);
    // Below the limit the value is exact, and each outermost loop has the whole budget again:
    // the sum of i j over 1..700 squared is 245350^2 (700 + 700^2 terms, twice per evaluation).
    EXPECT_EQ(error_of("#declare G = function(n) { sum(i, 1, 700, sum(j, 1, 700, i * j)) }\n"
                       "#declare H = function(n) { G(n) + G(n) }\n"
                       "#for (K, 1, 20) #if (H(K) != 120393245000) #error \"wrong\" #end #end\n"),
              "no error");
}

TEST(SceneLanguageLimits, ArraysAndStringsStopAtTheirSizeLimits) {
    EXPECT_EQ(error_of("#declare A = array[1e12];"),
              "array limit: more than 100000000 elements (ParseOptions::max_array_elements) at "
              "test.pov:1:20");
    EXPECT_EQ(error_of("#declare A = array[100000][100000];"),
              "array limit: more than 100000000 elements (ParseOptions::max_array_elements) at "
              "test.pov:1:28");
    EXPECT_EQ(error_of("#declare A = array[0];"),
              "an array dimension must be at least 1, found 0 at test.pov:1:20");
    ParseOptions options;
    options.max_string_length = 1000;
    EXPECT_EQ(
        error_of("#declare S = \"0123456789\";\n#while (1)\n  #declare S = concat(S, S);\n#end\n",
                 options),
        "string limit: a string of more than 1000 bytes (ParseOptions::max_string_length) at "
        "test.pov:3:16");
}

TEST(SceneLanguageLimits, HugeIndicesAndSizesAreErrorsNotConversions) {
    // Checked before they become integers (a float past the integer's range has none; the
    // first was found by fuzzing the scene reader, under UBSan).
    EXPECT_EQ(error_of("#declare S = array[3] {\"a\", \"b\", \"c\"}\n"
                       "#debug concat(S[6.6e71], \"x\")\n"),
              "array index 6.6e+71 out of range: dimension 1 has 3 elements (0 to 2) at "
              "test.pov:2:17");
    EXPECT_EQ(error_of("#declare A = array[3] {1, 2, 3}\n#declare X = A[2.9];\n"), "no error");
    EXPECT_EQ(error_of("#declare A = array[3] {1, 2, 3}\n#declare X = dimension_size(A, 1e30);\n"),
              "dimension_size: the array has 1 dimension, asked for dimension 2147483647 at "
              "test.pov:2:32");
    const std::string receiver =
        "illuminance_receiver { <0, 0, 0>, <1, 0, 0>, <0, 0, 1> resolution SIZE }\n";
    const auto with = [&](const std::string& size) {
        std::string text = receiver;
        return text.replace(text.find("SIZE"), 4, size);
    };
    EXPECT_EQ(error_of(with("<1e12, 1>")),
              "expected 'resolution <nx, ny>' with two whole numbers from 1 to 65536, at most "
              "16777216 cells in all, found <1000000000000, 1> at test.pov:1:67");
    EXPECT_NE(error_of(with("<4097, 4096>")).find("at most 16777216 cells"), std::string::npos);
    EXPECT_EQ(error_of(with("<4096, 4096>")), "no error");
}

TEST(SceneLanguageLimits, MemoryStopsAtItsLimitBeforeTheAllocationThatWouldPassIt) {
    ParseOptions options;
    options.max_memory_megabytes = 200;
    // Each array of 10^6 elements takes about 56 MB: the fourth would pass 200 MB.
    const auto start = std::chrono::steady_clock::now();
    const std::string e = error_of(
        "#declare L = array[100];\n#for (I, 0, 99)\n  #declare L[I] = array[1000000];\n#end\n",
        options);
    EXPECT_EQ(e,
              "memory limit: parsing the scene took more than 200 MB "
              "(ParseOptions::max_memory_megabytes, raytrace "
              "--max-parse-memory) at test.pov:3:19");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
              10.0);
    // Growth by many small values is caught by the periodic check as well.
    options.max_memory_megabytes = 50;
    const std::string growth = error_of(
        "#declare L = array[10000000];\n#for (I, 0, 9999999)\n  #declare L[I] = <I, I, I>;\n#end\n",
        options);
    EXPECT_NE(growth.find("memory limit: parsing the scene took more than 50 MB"),
              std::string::npos)
        << growth;
}

TEST(SceneLanguageLimits, ErrorsNameTheIncludeAndMacroChain) {
    test::ScratchDir dir;
    test::write_file(dir.file("lib.inc"), "#macro Bad(X)\n  #declare Y = X / 0;\n#end\n");
    test::write_file(dir.file("scene.pov"),
                     "#include \"lib.inc\"\n#macro Outer() Bad(1) #end\nOuter()\n");
    const std::string lib = std::filesystem::weakly_canonical(dir.file("lib.inc")).string();
    try {
        parse_scene_file(dir.file("scene.pov"));
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "division by zero at " + lib + ":2:18 (included from " + dir.file("scene.pov") +
                      ":1:1) (in macro Bad called at " + dir.file("scene.pov") +
                      ":2:16) (in macro Outer called at " + dir.file("scene.pov") + ":3:1)");
        EXPECT_EQ(e.where().line, 2);
        EXPECT_EQ(e.where().column, 18);  // the division sign
    }
}

}  // namespace
}  // namespace rayset::tracer

namespace rayset::tracer {
namespace {

TEST(SceneLanguageFiles, WritingNeedsAWriteRootAndStaysInsideIt) {
    test::ScratchDir dir;
    const std::filesystem::path previous = std::filesystem::current_path();
    std::filesystem::current_path(dir.path());
    const std::string scene = "#fopen F \"out.txt\" write\n#write (F, 1)\n#fclose F\n";
    EXPECT_EQ(error_of(scene),
              "#fopen \"out.txt\" for write: writing files is not allowed unless a folder is given "
              "for it (raytrace "
              "--allow-write DIR, or ParseOptions::write_roots) at test.pov:1:10");
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.txt")));
    ParseOptions options;
    options.write_roots = {dir.path().string()};
    EXPECT_EQ(error_of(scene, options), "no error");
    EXPECT_EQ(test::read_file(dir.file("out.txt")), "1");
    EXPECT_EQ(error_of("#fopen F \"../escape.txt\" append\n", options),
              "#fopen \"../escape.txt\" for append: writing files is not allowed outside the "
              "folders given for it "
              "(raytrace --allow-write DIR, or ParseOptions::write_roots) at test.pov:1:10");
    std::filesystem::current_path(previous);
}

// A name longer than the system allows (ENAMETOOLONG): read, it is not found; written, the
// system's reason is given. Both are scene errors at the name, not a std::filesystem exception.
TEST(SceneLanguageFiles, NamesTooLongForTheSystemAreSceneErrors) {
    const std::string name(5000, 'a');
    const std::string read = error_of("#fopen F \"" + name + "\" read\n");
    EXPECT_NE(read.find("#fopen file \"" + name + "\" not found"), std::string::npos) << read;
    EXPECT_NE(read.find("at test.pov:1:10"), std::string::npos) << read;
    ParseOptions options;
    options.write_roots = {std::filesystem::current_path().string()};
    const std::string written = error_of("#fopen F \"" + name + "\" write\n", options);
    EXPECT_NE(written.find("for write: File name too long at test.pov:1:10"), std::string::npos)
        << written;
}

}  // namespace
}  // namespace rayset::tracer

namespace rayset::tracer {
namespace {

TEST(SceneLanguageLimits, ALoopThatNeverEndsStopsAtTheLightOrObjectLimit) {
    // cornell.pov's light loop with j = j + 0: light sources without end, each one more.
    ParseOptions options;
    options.max_lights = 1000;
    const std::string lights =
        "#declare J = 0;\n#while (J < 3)\n  light_source { <J, 1, 0> rgb 1 }\n"
        "  #declare J = J + 0;\n#end\n";
    EXPECT_EQ(error_of(lights, options),
              "light limit: more than 1000 light sources in the scene (ParseOptions::max_lights, "
              "raytrace --max-lights) at test.pov:3:3");
    options.max_objects = 1000;
    EXPECT_EQ(error_of("#while (1)\n  union { sphere { 0, 1 } sphere { 1, 1 } }\n#end\n", options),
              "object limit: more than 1000 objects in the scene (ParseOptions::max_objects, "
              "raytrace --max-objects) at test.pov:2:3");
    // At the limit exactly is fine.
    EXPECT_EQ(error_of("#for (I, 1, 1000) light_source { <I, 1, 0> rgb 1 } #end", options),
              "no error");
    // The defaults stop cornell.pov's runaway loop within seconds, not gigabytes.
    const auto start = std::chrono::steady_clock::now();
    EXPECT_NE(error_of(lights).find("light limit: more than 100000 light sources"),
              std::string::npos);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
              30.0);
}

}  // namespace
}  // namespace rayset::tracer
