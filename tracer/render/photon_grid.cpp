// Hashed photon grid (see photon_grid.h).
#include "tracer/render/photon_grid.h"

#include <cmath>

namespace rayset::tracer {

template <class PhotonType>
PhotonGridOf<PhotonType>::PhotonGridOf(std::vector<Photon> photons, double radius)
    : photons_(std::move(photons)), radius_(radius) {
    // At least a row's three slots, so that a run wraps past the table's end at most once.
    table_size_ = std::max<size_t>(3, 2 * photons_.size());
    start_.assign(table_size_ + 1, 0);
    std::vector<size_t> slots(photons_.size());
    for (size_t i = 0; i < photons_.size(); ++i) {
        const Vec3 p = photons_[i].position;
        slots[i] = slot(cell_of(p.x), cell_of(p.y), cell_of(p.z));
        ++start_[slots[i] + 1];
    }
    for (size_t h = 0; h < table_size_; ++h) start_[h + 1] += start_[h];
    std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
    std::vector<uint32_t> order(photons_.size());
    for (size_t i = 0; i < photons_.size(); ++i) order[fill[slots[i]]++] = uint32_t(i);
    // Store the photons in slot order: a gather then reads each slot's photons contiguously.
    std::vector<Photon> sorted(photons_.size());
    positions_.resize(photons_.size());
    for (size_t k = 0; k < order.size(); ++k) {
        sorted[k] = photons_[order[k]];
        positions_[k] = sorted[k].position;
    }
    photons_ = std::move(sorted);
}

template class PhotonGridOf<PhotonOf<Rgb>>;
template class PhotonGridOf<PhotonOf<SampledSpectrum>>;

}  // namespace rayset::tracer
