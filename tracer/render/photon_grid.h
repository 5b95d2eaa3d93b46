// The photons of one pass in a hashed uniform grid (cell = the gather radius), so that a
// gather at a point visits the 27 cells around it. Built once per pass by a counting sort:
// the order is fixed by the photons' order, so gathers sum in a deterministic order.
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

template <class PhotonType>
class PhotonGridOf {
public:
    using Photon = PhotonType;
    PhotonGridOf(std::vector<Photon> photons, double radius);

    double radius() const { return radius_; }
    size_t size() const { return photons_.size(); }
    size_t memory_bytes() const {
        return photons_.size() * sizeof(Photon) + start_.size() * sizeof(uint32_t);
    }

    // Calls f(photon) for every photon within the radius of p.
    template <class F>
    void for_each_near(Vec3 p, F&& f) const {
        if (photons_.empty()) return;
        const int64_t cx = cell_of(p.x), cy = cell_of(p.y), cz = cell_of(p.z);
        const double r2 = radius_ * radius_;
        // Two of the 27 cells may share a slot: visit each slot once, or its photons count twice.
        size_t slots[27];
        int n = 0;
        for (int64_t dz = -1; dz <= 1; ++dz)
            for (int64_t dy = -1; dy <= 1; ++dy)
                for (int64_t dx = -1; dx <= 1; ++dx) slots[n++] = hash(cx + dx, cy + dy, cz + dz);
        std::sort(slots, slots + n);
        for (int s = 0; s < n; ++s) {
            if (s > 0 && slots[s] == slots[s - 1]) continue;
            for (uint32_t k = start_[slots[s]]; k < start_[slots[s] + 1]; ++k) {
                const Photon& photon = photons_[k];
                const Vec3 d = photon.position - p;
                if (dot(d, d) <= r2) f(photon);
            }
        }
    }

private:
    int64_t cell_of(double v) const { return int64_t(std::floor(v / radius_)); }
    size_t hash(int64_t x, int64_t y, int64_t z) const {
        // Teschner et al. 2003's spatial hash; distinct cells may share a slot (the distance
        // test above keeps gathers exact).
        const uint64_t h =
            uint64_t(x) * 73856093ULL ^ uint64_t(y) * 19349663ULL ^ uint64_t(z) * 83492791ULL;
        return size_t(h % table_size_);
    }

    std::vector<Photon> photons_;
    double radius_;
    size_t table_size_ = 1;
    std::vector<uint32_t> start_;  // photons of slot h: [start_[h], start_[h + 1])
};

using PhotonGrid = PhotonGridOf<Photon>;

}  // namespace rayset::tracer
