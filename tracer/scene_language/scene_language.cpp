// The top level of a scene file, the parser's set-up and limits, and the public entry points.
// A parse runs on a thread of its own with a large stack, so that the nesting limit, not the
// machine's default stack, bounds how deep a scene may recurse.
#include "tracer/scene_language/scene_language.h"

#include <pthread.h>
#include <unistd.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "tracer/scene_language/grammar.h"
#include "tracer/scene_language/parse_error.h"
#include "tracer/scene_language/parser.h"

namespace rayset::tracer {
namespace fs = std::filesystem;

namespace {

constexpr size_t kParserStackBytes = size_t{512} << 20;
constexpr const char* kPovRayIncludeFolder = "/usr/share/povray-3.7/include";

long resident_kilobytes() {
    std::FILE* statm = std::fopen("/proc/self/statm", "r");
    if (!statm) return 0;
    long total = 0, resident = 0;
    const int read = std::fscanf(statm, "%ld %ld", &total, &resident);
    std::fclose(statm);
    return read == 2 ? resident * (sysconf(_SC_PAGESIZE) / 1024) : 0;
}

// Runs `body` on a thread with a stack of `bytes`, rethrowing what it throws.
template <typename Body>
void run_with_stack(size_t bytes, Body&& body) {
    struct Task {
        Body* body;
        std::exception_ptr error;
    } task{&body, nullptr};
    auto trampoline = [](void* argument) -> void* {
        auto* t = static_cast<Task*>(argument);
        try {
            (*t->body)();
        } catch (...) {
            t->error = std::current_exception();
        }
        return nullptr;
    };
    pthread_attr_t attributes;
    pthread_attr_init(&attributes);
    pthread_attr_setstacksize(&attributes, bytes);
    pthread_t thread;
    const int created = pthread_create(&thread, &attributes, trampoline, &task);
    pthread_attr_destroy(&attributes);
    if (created != 0) {
        body();  // no thread: the caller's stack will have to do
        return;
    }
    pthread_join(thread, nullptr);
    if (task.error) std::rethrow_exception(task.error);
}

}  // namespace

std::vector<std::string> default_include_paths() {
    std::error_code error;
    if (fs::is_directory(kPovRayIncludeFolder, error)) return {kPovRayIncludeFolder};
    return {};
}

Parser::Parser(const ParseOptions& options)
    : options_(options), start_time_(std::chrono::system_clock::now()) {
    std::error_code error;
    search_paths_ = options.include_paths;
    for (const std::string& folder : default_include_paths()) search_paths_.push_back(folder);
    for (const std::string& folder : search_paths_)
        allowed_roots_.push_back(fs::weakly_canonical(folder, error).string());
    for (const std::string& folder : options.allowed_roots)
        allowed_roots_.push_back(fs::weakly_canonical(folder, error).string());
    for (const std::string& folder : options.write_roots)
        write_roots_.push_back(fs::weakly_canonical(folder, error).string());
    baseline_rss_kb_ = resident_kilobytes();
}

Parser::~Parser() = default;

static long memory_limit_megabytes(const ParseOptions& options) {
    if (options.max_memory_megabytes > 0) return options.max_memory_megabytes;
    const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGESIZE);
    return pages > 0 && page_size > 0 ? pages / 2 / (1048576 / page_size) : 4096;
}

void Parser::check_memory(const Token& at, double more_bytes) {
    tokens_since_memory_check_ = 0;
    const long limit = memory_limit_megabytes(options_);
    const double grown_mb =
        static_cast<double>(resident_kilobytes() - baseline_rss_kb_) / 1024 + more_bytes / 1048576;
    if (grown_mb > static_cast<double>(limit))
        fail(at, fmt::format("memory limit: parsing the scene took more than {} MB "
                             "(ParseOptions::max_memory_megabytes, "
                             "raytrace --max-parse-memory)",
                             limit));
}

SceneDescription Parser::parse(const std::string& text, const std::string& path) {
    std::error_code error;
    const fs::path directory = fs::absolute(fs::path(path), error).parent_path();
    allowed_roots_.insert(allowed_roots_.begin(), fs::weakly_canonical(directory, error).string());
    push_file(text, path, directory.string(), nullptr);
    for (const auto& [name, value] : options_.declarations) {
        const NameId id = names_.intern(name);
        if (is_keyword(id))
            throw Error(fmt::format("Declare={}: '{}' is a reserved word", name, name));
        assign(Token{}, id, Numeric::scalar(value), false);
    }

    for (;;) {
        const Token token = peek();
        if (token.kind == TokenKind::end) break;
        if (starts_object(*this, token)) {
            add_to_scene(*this, parse_object(*this), token);
            continue;
        }
        if (token.is(Symbol::semicolon)) {  // a stray ';' (POV-Ray ignores it)
            next();
            continue;
        }
        if (token.kind == TokenKind::word && (is_keyword(token.name) || !lookup_value(token))) {
            next();
            if (parse_scene_statement(*this, token)) continue;
        }
        fail_identifier(token,
                        "an object, a light_source, camera, global_settings, background, fog, "
                        "rainbow, sky_sphere, media, ray_source or illuminance_receiver");
    }
    return std::move(scene_);
}

SceneDescription parse_scene_text(const std::string& text, const std::string& virtual_path,
                                  const ParseOptions& options) {
    SceneDescription scene;
    run_with_stack(kParserStackBytes, [&] { scene = Parser(options).parse(text, virtual_path); });
    return scene;
}

SceneDescription parse_scene_file(const std::string& path, const ParseOptions& options) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(fmt::format("{}: cannot open scene file", path));
    std::ostringstream text;
    text << in.rdbuf();
    return parse_scene_text(text.str(), path, options);
}

}  // namespace rayset::tracer
