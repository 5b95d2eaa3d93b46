#include "fuzz/fuzz_support.h"

#include "converters/rays/ray_stream.h"
#include "core/error.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace rayset::fuzz {
namespace fs = std::filesystem;

namespace {

constexpr const char* kFolderPrefix = "rayset-fuzz-";

fs::path base_folder() {
    std::error_code error;
    const fs::path shm = "/dev/shm";
    return fs::is_directory(shm, error) ? shm : fs::temp_directory_path();
}

// The folders of harnesses that ended without running their exit handlers (a crash, a
// timeout, libFuzzer's _Exit), so that they do not pile up in memory.
void remove_folders_of_ended_processes(const fs::path& base) {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(base, error)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(kFolderPrefix, 0) != 0) continue;
        const long pid = std::strtol(name.c_str() + std::strlen(kFolderPrefix), nullptr, 10);
        if (pid > 0 && kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
            fs::remove_all(entry.path(), error);
    }
}

std::string& folder_path() {
    static std::string path;
    return path;
}

}  // namespace

// The folder is per process: libFuzzer's -jobs and -fork run several harnesses side by side.
const std::string& input_folder() {
    if (folder_path().empty()) {
        const fs::path base = base_folder();
        remove_folders_of_ended_processes(base);
        const fs::path folder = base / (kFolderPrefix + std::to_string(getpid()));
        fs::create_directories(folder);
        folder_path() = folder.string();
        std::atexit([] {
            std::error_code ignored;
            fs::remove_all(folder_path(), ignored);
        });
    }
    return folder_path();
}

std::string write_input(const uint8_t* data, size_t size, const std::string& name) {
    const std::string path = input_folder() + "/" + name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
        // A harness that cannot write its input would fuzz nothing: stop loudly.
        std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
        std::abort();
    }
    return path;
}

void expect_file_named(const Error& error, const std::string& path) {
    const std::string message = error.what();
    if (message.find(path) != std::string::npos) return;
    std::fprintf(stderr, "fuzz: an error that does not name the file %s: %s\n", path.c_str(),
                 message.c_str());
    std::abort();
}

void read_every_ray(const std::string& path, std::optional<RayFormat> format) {
    RayReadOptions options;
    options.format = format;
    // Real files are read 4096 rays at a time; the fuzzer's inputs hold a few hundred rays at
    // most, so a small odd chunk makes them cross the chunk boundaries large files cross.
    options.chunk_size = 13;
    try {
        auto reader = open_rays(path, options);
        RayChunk chunk;
        while (reader->read(chunk)) {
        }
    } catch (const Error& error) {
        // The reader found the file bad and said where: what it should do.
        expect_file_named(error, path);
    }
}

}  // namespace rayset::fuzz
