#include "lightmodel/coverage.h"

#include "core/random.h"
#include "lightmodel/emission_volume.h"
#include "lightmodel/sphere_body.h"

#include <tbb/parallel_for.h>

namespace rayset::lightmodel {

void measure_visible_fractions(LightModel& model, int lines, uint64_t seed) {
    for (FluxCell& c : model.flux_cells) c.visible_fraction = 1;
    const SphereBody body(model.spheres);
    const EmissionVolume volume(model);
    const Box bounds = model.bounds();
    const double reach = length(bounds.extent()) + model.density_frame.cell_size();
    tbb::parallel_for(size_t(0), model.flux_cells.size(), [&](size_t c) {
        Pcg32 rng(seed, c);
        const GoniometricDiagram& diagram =
            model.diagrams[size_t(model.flux_cells[c].intensity_cell)];
        int hits = 0;
        for (int i = 0; i < lines; ++i) {
            const Vec3 x = volume.sample_in_cell(uint32_t(c), rng.uniform(),
                                                 {rng.uniform(), rng.uniform(), rng.uniform()});
            const Vec3 w = diagram.sample({rng.uniform(), rng.uniform()}).direction;
            BodyHit hit;
            hits += body.intersect(x - reach * w, w, 2 * reach, hit) ? 1 : 0;
        }
        // A cell the body hides completely shows nothing whatever g is; 1 avoids dividing by 0.
        model.flux_cells[c].visible_fraction = hits > 0 ? double(hits) / lines : 1.0;
    });
}

}  // namespace rayset::lightmodel
