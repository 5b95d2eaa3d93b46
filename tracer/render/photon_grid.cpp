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
    // Slots and photon indices fit 32 bits: a pass's photons are far fewer than 2^31 (200 GB).
    std::vector<uint32_t> slots(photons_.size());
    for (size_t i = 0; i < photons_.size(); ++i) {
        const Vec3 p = photons_[i].position;
        slots[i] = uint32_t(slot(cell_of(p.x), cell_of(p.y), cell_of(p.z)));
        ++start_[slots[i] + 1];
    }
    for (size_t h = 0; h < table_size_; ++h) start_[h + 1] += start_[h];
    // Store the photons in slot order: a gather then reads each slot's photons contiguously.
    std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
    std::vector<Photon> sorted(photons_.size());
    positions_.resize(photons_.size());
    for (size_t i = 0; i < photons_.size(); ++i) {
        const uint32_t k = fill[slots[i]]++;
        sorted[k] = photons_[i];
        positions_[k] = photons_[i].position;
    }
    photons_ = std::move(sorted);
}

template class PhotonGridOf<PhotonOf<Rgb>>;
template class PhotonGridOf<PhotonOf<SampledSpectrum>>;
template class PhotonGridOf<IndexedPoint>;

}  // namespace rayset::tracer
