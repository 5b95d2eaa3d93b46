// Makes the seed corpora of the harnesses (scripts/fuzz.sh runs it before fuzzing): for every
// ray format, small files that the project's own encoders write from analytic sources and from
// the first rays of each real ray file; the real ray files small enough to be inputs as they
// are, and the first bytes of the large ones (their headers); the real photometry files, each
// also written in the other photometric format; a few OBJ meshes. Nothing it writes goes into the
// repository.
//
// Usage: fuzz_seeds OUT_FOLDER [SHARED_DATA_FOLDER]
//   writes OUT_FOLDER/<harness>/<seed>; without the shared data only the analytic seeds.
#include "converters/analytic/synth.h"
#include "converters/photometry/photometry.h"
#include "converters/rays/ray_stream.h"
#include "core/error.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace rayset;

namespace {

// Inputs larger than the harnesses' -max_len are cut by libFuzzer anyway; a TM-25 header alone
// is 36288 bytes.
constexpr uintmax_t kLargestSeedBytes = 65536;
constexpr uint64_t kRaysPerSeed = 11;

// The harness that reads each format (fuzz/<harness>_fuzzer.cpp) and a file extension for it.
struct FormatSeeds {
    RayFormat format;
    const char* harness;
    const char* extension;
};
constexpr FormatSeeds kFormats[] = {
    {RayFormat::tm25, "tm25", ".tm25ray"},
    {RayFormat::lighttools_binary, "lighttools_binary", ".ray"},
    {RayFormat::lighttools_text, "lighttools_text", ".txt"},
    {RayFormat::zemax_binary, "zemax_binary", ".dat"},
    {RayFormat::zemax_text, "zemax_text", ".txt"},
    {RayFormat::speos, "speos", ".ray"},
    {RayFormat::csv, "csv", ".csv"},
};

const FormatSeeds& seeds_of(RayFormat format) {
    for (const FormatSeeds& f : kFormats)
        if (f.format == format) return f;
    throw Error("no harness for ray format " + std::string(to_string(format)));
}

class SeedFolder {
public:
    explicit SeedFolder(fs::path root) : root_(std::move(root)) {}

    fs::path path(const std::string& harness, const std::string& name) const {
        fs::create_directories(root_ / harness);
        return root_ / harness / name;
    }

    // The first `bytes` of `source` (all of it when it is shorter) as a seed of `harness`.
    void copy(const fs::path& source, const std::string& harness, const std::string& name,
              uintmax_t bytes = kLargestSeedBytes) const {
        std::ifstream in(source, std::ios::binary);
        std::string content(static_cast<size_t>(std::min(fs::file_size(source), bytes)), '\0');
        in.read(content.data(), static_cast<std::streamsize>(content.size()));
        std::ofstream(path(harness, name), std::ios::binary) << content;
    }

private:
    fs::path root_;
};

// Writes `rays` into every format (those that cannot hold the header are skipped): seeds of
// each format's harness and of the detection harness.
void write_every_format(const SeedFolder& seeds, const std::string& stem, const RayHeader& header,
                        const RayChunk& rays) {
    for (const FormatSeeds& f : kFormats) {
        const std::string name = stem + f.extension;
        const fs::path path = seeds.path(f.harness, name);
        try {
            auto encoder = create_rays(path.string(), f.format, header);
            encoder->write(rays);
            encoder->finish();
            fs::copy_file(path, seeds.path("ray_detect", f.harness + ("_" + name)),
                          fs::copy_options::overwrite_existing);
        } catch (const Error&) {
            // Not every format holds every header (SPEOS needs wavelengths and radiant flux).
        }
    }
}

// Analytic sources of each spectral kind: one wavelength, a wavelength per ray (the cluster's
// chips), a spectral table (when the shared data has a spectrum file).
void analytic_seeds(const SeedFolder& seeds, const fs::path& shared) {
    std::vector<std::pair<std::string, SourceParameters>> sources = {
        {"disk", {{"radius", "1"}, {"wavelength", "450"}}},
        {"sphere", {{"radius", "0.5"}, {"flux", "2"}}},
        {"lobe", {{"n", "3"}}},
        {"cluster", {{"rings", "1,6"}}},
    };
    const fs::path spectrum =
        shared / "rayfiles/LERTDUW_S2WP_binBQ_white-blue_20110706_spectrum.txt";
    std::error_code error;
    if (fs::is_regular_file(spectrum, error))
        sources.push_back({"rectangle", {{"size_x", "2"}, {"spectrum", spectrum.string()}}});
    for (bool luminous : {false, true}) {
        for (const auto& [name, parameters] : sources) {
            const auto source = make_source(name, parameters);
            SynthOptions options;
            options.luminous = luminous;
            const RayHeader header = synth_header(*source, kRaysPerSeed, 1, options);
            // synthesize() writes into an encoder: keep its rays in memory instead.
            struct Collect : RayEncoder {
                RayChunk rays;
                void write(const RayChunk& chunk) override {
                    rays.rays.insert(rays.rays.end(), chunk.rays.begin(), chunk.rays.end());
                    rays.extra.insert(rays.extra.end(), chunk.extra.begin(), chunk.extra.end());
                }
                void finish() override {}
            } collect;
            synthesize(*source, kRaysPerSeed, 1, collect, options);
            write_every_format(seeds, name + (luminous ? "_luminous" : "_radiant"), header,
                               collect.rays);
        }
    }
}

// Each real ray file: as it is when small, its first bytes when large, and its first rays in
// every format.
void real_ray_seeds(const SeedFolder& seeds, const fs::path& folder) {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(folder, error)) {
        if (!entry.is_regular_file()) continue;
        const fs::path& path = entry.path();
        RayFormat format;
        try {
            format = detect_ray_format(path.string());
        } catch (const Error&) {
            continue;  // the spectrum, licences, the PDF sheet
        }
        const std::string name = path.filename().string();
        seeds.copy(path, seeds_of(format).harness, name);
        seeds.copy(path, "ray_detect", name);
        try {
            RayReadOptions options;
            options.chunk_size = kRaysPerSeed;
            auto reader = open_rays(path.string(), options);
            RayChunk rays;
            if (reader->read(rays))
                write_every_format(seeds, "first_rays_of_" + name, reader->file_header(), rays);
        } catch (const Error& e) {
            std::fprintf(stderr, "fuzz_seeds: %s\n", e.what());
        }
    }
}

// Each real photometry file as it is, and written in the other format.
void photometry_seeds(const SeedFolder& seeds, const fs::path& folder) {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(folder, error)) {
        if (!entry.is_regular_file()) continue;
        const fs::path& path = entry.path();
        try {
            const bool ies = detect_photometry_format(path.string()) == PhotometryFormat::ies;
            seeds.copy(path, ies ? "ies" : "eulumdat", path.filename().string());
            const Photometry photometry = read_photometry(path.string());
            const fs::path other = seeds.path(ies ? "eulumdat" : "ies",
                                              path.stem().string() + (ies ? ".ldt" : ".ies"));
            try {
                write_photometry(other.string(), photometry,
                                 ies ? PhotometryFormat::eulumdat : PhotometryFormat::ies);
            } catch (const Error&) {
                // EULUMDAT holds type C photometry only.
            }
        } catch (const Error& e) {
            std::fprintf(stderr, "fuzz_seeds: %s\n", e.what());
        }
    }
}

// Hand-made OBJ meshes (the repository holds none): each statement and index form the loader
// meets in exported files.
void mesh_seeds(const SeedFolder& seeds) {
    const std::pair<const char*, const char*> meshes[] = {
        {"triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
        {"quad_normals.obj",
         "# a quad with a normal per corner\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
         "vn 0 0 1\nf 1//1 2//1 3//1 4//1\n"},
        {"textured.obj",
         "mtllib parts.mtl\no part\ng top bottom\nusemtl steel\ns 1\nv 0 0 0\nv 1 0 0\n"
         "v 1 1 0\nv 0 1 1.5e-3\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nvn 0 0.6 0.8\n"
         "f 1/1/1 2/2/1 3/3/2\nf 1/1/1 3/3/2 4/2/2\n"},
        {"relative_pentagon.obj",
         "v 1 0 0\nv 0.31 0.95 0\nv -0.81 0.59 0\nv -0.81 -0.59 0\nv 0.31 -0.95 0\n"
         "f -5 -4 -3 -2 -1\nl 1 2\np 3\n"},
    };
    for (const auto& [name, text] : meshes) std::ofstream(seeds.path("mesh", name)) << text;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: fuzz_seeds OUT_FOLDER [SHARED_DATA_FOLDER]\n");
        return 2;
    }
    const SeedFolder seeds(argv[1]);
    const fs::path shared = argc == 3 ? fs::path(argv[2]) : fs::path();
    try {
        analytic_seeds(seeds, shared);
        mesh_seeds(seeds);
        std::error_code error;
        if (!shared.empty() && fs::is_directory(shared, error)) {
            real_ray_seeds(seeds, shared / "rayfiles");
            photometry_seeds(seeds, shared / "photometry");
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_seeds: %s\n", e.what());
        return 1;
    }
    return 0;
}
