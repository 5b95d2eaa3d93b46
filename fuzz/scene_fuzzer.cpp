// Fuzzes the scene language: each input is a scene that parse_scene_text() reads - lexer,
// directives and macros, expressions, functions and the grammar of every scene item - as
// `raytrace --parse-only` reads a scene file (parse_scene_file reads the file, then this). The
// scene names a file in a folder of its own, so that #include, image and font names resolve
// there or in POV-Ray's include folder, and #fopen may write nowhere.
#include "core/error.h"
#include "fuzz/fuzz_support.h"
#include "tracer/scene_language/scene_language.h"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    rayset::tracer::ParseOptions options;
    // Tighter than the defaults, which allow what a real scene may take (10^8 loop iterations,
    // half the RAM): each input must finish in well under libFuzzer's -timeout and its
    // -rss_limit_mb, so that a hang or an allocation that escapes these limits stands out. An
    // iteration may trace a lathe and format its result (200 us here under the sanitizers):
    // 10^4 of them take 2 s.
    options.max_loop_iterations = 10000;
    options.max_macro_calls = 10000;  // 50 us each here: 0.5 s
    options.max_array_elements = 1000000;
    options.max_string_length = 1000000;
    options.max_memory_megabytes = 512;
    options.on_message = [](rayset::tracer::MessageStream, const std::string&) {};
    // The text is parsed from memory; the file it names need not exist.
    const std::string path = rayset::fuzz::input_folder() + "/scene.pov";
    try {
        rayset::tracer::parse_scene_text(std::string(reinterpret_cast<const char*>(data), size),
                                         path, options);
    } catch (const rayset::Error& error) {
        // The parser found the scene bad (or over a limit) and said where: what it should do.
        rayset::fuzz::expect_file_named(error, path);
    }
    return 0;
}
