// The integrators by name, and the records the pass driver shares with them (integrator.h).
#include "tracer/render/integrator.h"

#include <fmt/format.h>

#include "core/error.h"
#include "tracer/render/bidirectional_integrator.h"
#include "tracer/render/path_integrator.h"
#include "tracer/render/renderer.h"
#include "tracer/render/vcm_integrator.h"

namespace rayset::tracer {

namespace {

struct IntegratorEntry {
    const char* name;
    std::vector<std::string> layers;
    std::unique_ptr<Integrator> (*make)(const RenderScene&, const RenderSettings&,
                                        const RenderResult&);
};

const std::vector<IntegratorEntry>& integrators() {
    static const std::vector<IntegratorEntry> entries = {
        {"path", light_layers(), make_path_integrator},
        {"bidirectional", light_layers(), make_bidirectional_integrator},
        {"vcm", light_layers(), make_vcm_integrator},
    };
    return entries;
}

const IntegratorEntry& integrator_named(const std::string& name) {
    for (const IntegratorEntry& entry : integrators())
        if (name == entry.name) return entry;
    throw Error("unknown integrator \"" + name + "\" (expected " + integrator_names_text() + ")");
}

}  // namespace

const std::vector<std::string>& light_layers() {
    static const std::vector<std::string> names = {"direct_visibility", "primary", "secondary"};
    return names;
}

SamplePoints::SamplePoints(const RenderSettings& settings,
                           const std::vector<ReceiverMap>& receivers)
    : width(settings.render_image ? settings.width : 0),
      height(settings.render_image ? settings.height : 0),
      tile_size(settings.tile_size),
      first_cell_stream(uint64_t(settings.width) * settings.height),
      receivers(&receivers) {
    size_t first = 0;
    for (const ReceiverMap& map : receivers)
        receiver_first.push_back(first), first += size_t(map.irradiance.nx()) * map.irradiance.ny();
}

size_t SamplePoints::cells() const {
    if (receivers->empty()) return 0;
    const SampleGrid& last = receivers->back().irradiance;
    return receiver_first.back() + size_t(last.nx()) * last.ny();
}

PassValues::PassValues(int components, size_t points)
    : components(size_t(components), std::vector<Rgb>(points)) {}

Rgb PassValues::total(size_t i) const {
    Rgb sum = components[0][i];
    for (size_t c = 1; c < components.size(); ++c) sum += components[c][i];
    return sum;
}

std::unique_ptr<Integrator> make_integrator(const RenderScene& scene,
                                            const RenderSettings& settings,
                                            const RenderResult& start) {
    return integrator_named(scene.description().global.integrator).make(scene, settings, start);
}

std::vector<std::string> integrator_layers(const std::string& name) {
    return integrator_named(name).layers;
}

LightPathBudget light_path_budget(const RenderScene& scene, const RenderSettings& settings) {
    size_t points = settings.render_image ? size_t(settings.width) * settings.height : 0;
    for (const IlluminanceReceiver& r : scene.description().receivers)
        points += size_t(r.nx) * r.ny;
    LightPathBudget budget;
    budget.light_paths = settings.photons_per_pass > 0
                             ? uint64_t(settings.photons_per_pass)
                             : std::max<uint64_t>(kMinimumLightPathsPerPass, points);
    budget.camera_samples =
        int(std::max<uint64_t>(1, budget.light_paths / std::max<uint64_t>(1, points)));
    return budget;
}

bool spectral_transport(const RenderScene& scene, const RenderSettings& settings) {
    const bool spectral = settings.spectral || scene.description().global.spectral;
    // A colour fitted to a spectrum at every point a path meets would cost more than the path.
    if (spectral && scene.has_varying_colours())
        throw Error(
            "not supported: patterned pigments, a sky_sphere or fog in spectral transport (render "
            "in "
            "RGB: without "
            "--spectral and without global_settings { spectral on })");
    return spectral;
}

void refuse_what_light_paths_do_not_carry(const RenderScene& scene, const std::string& integrator) {
    for (const LightSource& light : scene.description().lights)
        if (light.shadowless)
            throw Error(
                fmt::format("not supported: a shadowless light_source with integrator "
                            "\"{}\" at {} (the path integrator renders it)",
                            integrator, light.location.str()));
    if (scene.fog().present())
        throw Error(
            fmt::format("not supported: fog with integrator \"{}\" at {} (the path "
                        "integrator renders it)",
                        integrator, scene.description().atmosphere.fogs.front().location.str()));
}

}  // namespace rayset::tracer
