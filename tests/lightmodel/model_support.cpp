#include "lightmodel/model_support.h"

#include "converters/analytic/synth.h"
#include "converters/rays/ray_stream.h"
#include "lightmodel/model_file.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <system_error>

namespace fs = std::filesystem;

namespace rayset::test {

namespace {

std::unique_ptr<analytic::Source> make_truth(const std::string& name) {
    using namespace analytic;
    Spectrum spectrum;
    spectrum.wavelength_nm = 555;
    if (name == "disk" || name == "disk4m")
        return std::make_unique<LambertianDisk>(LambertianDisk::with_flux(1, 1, spectrum));
    if (name == "sphere")
        return std::make_unique<LambertianSphere>(LambertianSphere::with_flux(1, 1, spectrum));
    if (name == "lobe") return std::make_unique<CosineLobe>(CosineLobe::with_flux(4, 1, spectrum));
    return std::make_unique<ChipCluster>(ChipCluster::Layout{}, std::vector<double>{1.0 / 39},
                                         std::vector<double>{460, 530, 620});
}

// An exclusive lock on a file, shared by every process and thread that locks the same path
// (flock), released when the object goes away.
class FileLock {
public:
    explicit FileLock(const fs::path& path)
        : fd_(::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
        if (fd_ < 0) throw std::system_error(errno, std::generic_category(), path.string());
        while (::flock(fd_, LOCK_EX) != 0)
            if (errno != EINTR) throw std::system_error(errno, std::generic_category(), "flock");
    }
    ~FileLock() { ::close(fd_); }
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;

private:
    int fd_;
};

// test-cache/<test binary>/ in the build tree (`base`), and in it the folder of this binary's
// build, named by the binary's size and modification time.
struct CacheFolders {
    fs::path base, build;
};
CacheFolders cache_folders() {
    const fs::path binary = fs::canonical("/proc/self/exe");
    const fs::path base = fs::path(RAYSET_BINARY_DIR) / "test-cache" / binary.filename();
    return {base, base / (std::to_string(fs::file_size(binary)) + "-" +
                          std::to_string(fs::last_write_time(binary).time_since_epoch().count()))};
}

}  // namespace

ModelFiles synthesised_model(const std::string& folder, const std::string& key,
                             const analytic::Source& source, uint64_t rays, uint64_t seed) {
    const auto [base, cache] = cache_folders();
    const std::string stem = key + "-" + std::to_string(rays) + "-" + std::to_string(seed);
    const fs::path rays_file = cache / (stem + ".tm25ray"), model_file = cache / (stem + ".vdb");
    {
        fs::create_directories(cache);
        const FileLock lock(base / "lock");
        for (const fs::directory_entry& older : fs::directory_iterator(base))
            if (older.is_directory() && older.path() != cache) fs::remove_all(older.path());
        // Both files are written atomically, the model last: a model there is a whole pair.
        if (!fs::exists(model_file)) {
            {
                auto out = create_rays(rays_file.string(), RayFormat::tm25,
                                       synth_header(source, rays, seed));
                synthesize(source, rays, seed, *out);
            }
            lightmodel::write_model(lightmodel::build_model(rays_file.string(), {}),
                                    model_file.string());
        }
    }
    const ModelFiles placed{(fs::path(folder) / (key + ".tm25ray")).string(),
                            (fs::path(folder) / (key + ".vdb")).string()};
    fs::copy_file(rays_file, placed.rays, fs::copy_options::overwrite_existing);
    fs::copy_file(model_file, placed.model, fs::copy_options::overwrite_existing);
    return placed;
}

const BuiltSource& built_source(const std::string& name) {
    static std::mutex mutex;
    static std::map<std::string, BuiltSource> built;
    static ScratchDir scratch;
    std::lock_guard<std::mutex> lock(mutex);
    auto found = built.find(name);
    if (found != built.end()) return found->second;

    BuiltSource b;
    b.truth = make_truth(name);
    const ModelFiles files = synthesised_model(scratch.path().string(), name, *b.truth,
                                               name == "disk4m" ? 4000000 : 1000000, 7);
    b.ray_file = files.rays;
    {
        auto reader = open_rays(b.ray_file);
        RayChunk chunk;
        while (reader->read(chunk)) {
        }
        b.ray_flux = reader->totals().radiant;
    }
    b.model = std::make_shared<lightmodel::LightModel>(lightmodel::read_model(files.model));
    b.source = std::make_unique<lightmodel::ComplexSource>(b.model);
    return built.emplace(name, std::move(b)).first->second;
}

}  // namespace rayset::test
