// The photons of one pass in a hashed uniform grid (cell = the gather radius), so that a
// gather at a point visits the 27 cells around it. A row of cells along x hashes to consecutive
// slots, so a gather reads nine runs of three slots, each one range of photons, instead of 27
// scattered slots. Built once per pass by a counting sort: the order is fixed by the photons'
// order, so gathers sum in a deterministic order. A grid rebuilt for the next pass (assign())
// keeps its storage: tens of megabytes a pass, which the system would otherwise map afresh and
// fault in page by page. The positions are kept apart from the rest of each photon: a gather
// tests many photons' distance for each one it uses, and reads 24 bytes for a test instead of
// the whole photon.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tracer/render/rgb.h"
#include "tracer/render/spectrum.h"

namespace rayset::tracer {

// The photon's wavelengths when spectral (a base, so that RGB photons hold nothing more).
template <class Q>
struct PhotonWavelengths {};
template <>
struct PhotonWavelengths<SampledSpectrum> {
    SampledWavelengths wavelengths;
};

template <class Q>
struct PhotonOf : PhotonWavelengths<Q> {
    Vec3 position;
    Vec3 wi;              // unit, toward where the photon came from
    Vec3 normal;          // unit surface normal on the side the photon arrived at
    Q power;              // W (per nm at its wavelengths when spectral)
    bool direct = false;  // no scattering since the source (only the naive model keeps these)
};
using Photon = PhotonOf<Rgb>;

// PhotonType: anything with a `position`.
template <class PhotonType>
class PhotonGridOf {
public:
    using Photon = PhotonType;
    PhotonGridOf() = default;  // empty
    PhotonGridOf(const std::vector<Photon>& photons, double radius) { assign(photons, radius); }

    // The grid of `photons` (copied) with cells of `radius`, in place of what it held; with
    // `keep`, of those photons p for which keep(p) is true alone.
    void assign(const std::vector<Photon>& photons, double radius) {
        assign(photons, radius, [](const Photon&) { return true; });
    }
    template <class Keep>
    void assign(const std::vector<Photon>& photons, double radius, Keep&& keep);

    double radius() const { return radius_; }
    size_t size() const { return photons_.size(); }
    size_t memory_bytes() const {
        return photons_.size() * (sizeof(Photon) + sizeof(Vec3)) + start_.size() * sizeof(uint32_t);
    }

    // Calls f(photon) for every photon within the radius of p.
    template <class F>
    void for_each_near(Vec3 p, F&& f) const {
        if (photons_.empty()) return;
        const int64_t cx = cell_of(p.x), cy = cell_of(p.y), cz = cell_of(p.z);
        const double r2 = radius_ * radius_;
        // The slot runs of the nine rows; two rows may share slots (or wrap past the table's
        // end): visit each slot once, or its photons count twice.
        SlotRun runs[18];
        int n = 0;
        for (int64_t dz = -1; dz <= 1; ++dz)
            for (int64_t dy = -1; dy <= 1; ++dy) {
                const size_t first = slot(cx - 1, cy + dy, cz + dz);
                const size_t last = first + 3;
                if (last <= table_size_) {
                    runs[n++] = {first, last};
                } else {
                    runs[n++] = {first, table_size_};
                    runs[n++] = {0, last - table_size_};
                }
            }
        std::sort(runs, runs + n, [](SlotRun a, SlotRun b) { return a.first < b.first; });
        size_t visited = 0;  // every slot below it is done
        for (int i = 0; i < n; ++i) {
            const size_t first = std::max(runs[i].first, visited);
            if (first >= runs[i].last) continue;
            visited = runs[i].last;
            for (uint32_t k = start_[first]; k < start_[runs[i].last]; ++k) {
                const Vec3 d = positions_[k] - p;
                if (dot(d, d) <= r2) f(photons_[k]);
            }
        }
    }

private:
    struct SlotRun {
        size_t first, last;  // slots [first, last)
    };
    int64_t cell_of(double v) const { return int64_t(std::floor(v / radius_)); }
    // Cell (x, y, z)'s slot: its row's hash plus x, so that x and x + 1 are neighbouring slots.
    // The table is a power of two, so wrapping is a mask: the hash is Teschner et al. 2003's of
    // the row, mixed by Fibonacci hashing into the table's bits (distinct cells may share a
    // slot; the distance test above keeps gathers exact).
    size_t slot(int64_t x, int64_t y, int64_t z) const {
        const uint64_t row = uint64_t(y) * 19349663ULL ^ uint64_t(z) * 83492791ULL;
        return size_t(((row * 0x9E3779B97F4A7C15ULL) >> hash_shift_) + uint64_t(x)) & slot_mask_;
    }

    std::vector<Photon> photons_;  // in slot order
    std::vector<Vec3> positions_;  // photons_[k].position
    double radius_ = 1;
    size_t table_size_ = 1;
    uint64_t slot_mask_ = 0;                // table_size_ - 1
    int hash_shift_ = 63;                   // 64 - log2(table_size_)
    std::vector<uint32_t> start_;           // photons of slot h: [start_[h], start_[h + 1])
    std::vector<uint32_t> slot_of_, fill_;  // assign()'s scratch: each photon's slot, next free
};

template <class PhotonType>
template <class Keep>
void PhotonGridOf<PhotonType>::assign(const std::vector<Photon>& photons, double radius,
                                      Keep&& keep) {
    radius_ = radius;
    // Slots and photon indices fit 32 bits: a pass's photons are far fewer than 2^31 (200 GB).
    constexpr uint32_t kLeftOut = ~0u;
    slot_of_.resize(photons.size());
    size_t n = 0;
    for (size_t i = 0; i < photons.size(); ++i) {
        slot_of_[i] = keep(photons[i]) ? 0 : kLeftOut;
        n += slot_of_[i] != kLeftOut;
    }
    // At least twice the photons, and a row's three slots, so that a run wraps past the table's
    // end at most once.
    table_size_ = 4;
    hash_shift_ = 62;
    while (table_size_ < 2 * n) table_size_ *= 2, --hash_shift_;
    slot_mask_ = table_size_ - 1;
    start_.assign(table_size_ + 1, 0);
    for (size_t i = 0; i < photons.size(); ++i) {
        if (slot_of_[i] == kLeftOut) continue;
        const Vec3 p = photons[i].position;
        slot_of_[i] = uint32_t(slot(cell_of(p.x), cell_of(p.y), cell_of(p.z)));
        ++start_[slot_of_[i] + 1];
    }
    for (size_t h = 0; h < table_size_; ++h) start_[h + 1] += start_[h];
    // Store the photons in slot order: a gather then reads each slot's photons contiguously.
    fill_.assign(start_.begin(), start_.end() - 1);
    photons_.resize(n);
    positions_.resize(n);
    for (size_t i = 0; i < photons.size(); ++i) {
        if (slot_of_[i] == kLeftOut) continue;
        const uint32_t k = fill_[slot_of_[i]]++;
        photons_[k] = photons[i];
        positions_[k] = photons[i].position;
    }
}

using PhotonGrid = PhotonGridOf<Photon>;

}  // namespace rayset::tracer
