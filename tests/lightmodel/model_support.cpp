#include "lightmodel/model_support.h"

#include "converters/analytic/synth.h"
#include "converters/rays/ray_stream.h"

#include <mutex>

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

}  // namespace

const BuiltSource& built_source(const std::string& name) {
    static std::mutex mutex;
    static std::map<std::string, BuiltSource> built;
    static ScratchDir scratch;
    std::lock_guard<std::mutex> lock(mutex);
    auto found = built.find(name);
    if (found != built.end()) return found->second;

    BuiltSource b;
    b.truth = make_truth(name);
    b.ray_file = scratch.file(name + ".tm25ray");
    const uint64_t rays = name == "disk4m" ? 4000000 : 1000000, seed = 7;
    {
        auto out = create_rays(b.ray_file, RayFormat::tm25, synth_header(*b.truth, rays, seed));
        synthesize(*b.truth, rays, seed, *out);
    }
    {
        auto reader = open_rays(b.ray_file);
        RayChunk chunk;
        while (reader->read(chunk)) {
        }
        b.ray_flux = reader->totals().radiant;
    }
    b.model = std::make_shared<lightmodel::LightModel>(lightmodel::build_model(b.ray_file, {}));
    b.source = std::make_unique<lightmodel::ComplexSource>(b.model);
    return built.emplace(name, std::move(b)).first->second;
}

}  // namespace rayset::test
