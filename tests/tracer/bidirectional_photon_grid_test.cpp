// The photon grid's gathers against brute force: every photon within the radius is visited
// exactly once, at random points and at the symmetric ones (coordinates 0 and whole cells)
// where neighbouring cells of the spatial hash are most likely to share a slot.
#include <gtest/gtest.h>

#include "core/random.h"
#include "tracer/render/photon_grid.h"

namespace rayset::tracer {
namespace {

TEST(BidirectionalPhotonGrid, GatherVisitsEachPhotonWithinTheRadiusOnce) {
    Pcg32 rng(17, 3);
    std::vector<Photon> photons;
    for (int i = 0; i < 20000; ++i) {
        Photon p;
        p.position = {100 * rng.uniform() - 50, 100 * rng.uniform() - 50, 100 * rng.uniform() - 50};
        p.power = {double(i), 0, 0};  // the index, to tell photons apart
        photons.push_back(p);
    }
    const double radius = 3;
    const PhotonGrid grid(photons, radius);
    std::vector<Vec3> points{{0, 0, 0},   {0, 50, 0}, {50, 0, 0},
                             {0, -50, 0}, {3, 3, -3}, {-3, 0, 3}};
    for (int i = 0; i < 500; ++i)
        points.push_back(
            {100 * rng.uniform() - 50, 100 * rng.uniform() - 50, 100 * rng.uniform() - 50});
    for (const Vec3& p : points) {
        std::vector<int> visits(photons.size(), 0);
        grid.for_each_near(p, [&](const Photon& photon) { ++visits[size_t(photon.power.red)]; });
        for (size_t i = 0; i < photons.size(); ++i) {
            const Vec3 d = photons[i].position - p;
            const int expected = dot(d, d) <= radius * radius ? 1 : 0;
            ASSERT_EQ(visits[i], expected)
                << "photon " << i << " at point " << p.x << "," << p.y << "," << p.z;
        }
    }
}

}  // namespace
}  // namespace rayset::tracer
