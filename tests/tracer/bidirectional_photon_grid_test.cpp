// The photon grid's gathers against brute force: every photon within the radius is visited
// exactly once, at random points and at the symmetric ones (coordinates 0 and whole cells)
// where neighbouring cells of the spatial hash are most likely to share a slot, and with so few
// photons that the rows' runs of slots overlap and wrap past the table's end in most gathers;
// and each photon found again by the order it was given in. A grid of some of the photons
// (assign's `keep`) finds those and no other.
#include <gtest/gtest.h>

#include "core/random.h"
#include "tracer/render/photon_grid.h"

namespace rayset::tracer {
namespace {

// `keep_every`: the grid holds photons 0, k, 2k ... of those drawn.
void expect_each_photon_within_the_radius_visited_once(int count, int keep_every) {
    Pcg32 rng(17, 3);
    std::vector<Photon> photons;
    for (int i = 0; i < count; ++i) {
        Photon p;
        p.position = {100 * rng.uniform() - 50, 100 * rng.uniform() - 50, 100 * rng.uniform() - 50};
        p.power = {double(i), 0, 0};  // the index, to tell photons apart
        photons.push_back(p);
    }
    // Few photons crowd into a few cells around the middle, so that gathers find some.
    const double radius = count < 100 ? 30 : 3;
    PhotonGrid grid;
    grid.assign(photons, radius,
                [&](const Photon& photon) { return int(photon.power.red) % keep_every == 0; });
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
            const int expected = dot(d, d) <= radius * radius && i % keep_every == 0 ? 1 : 0;
            ASSERT_EQ(visits[i], expected)
                << count << " photons, every " << keep_every << ": photon " << i << " at point "
                << p.x << "," << p.y << "," << p.z;
        }
    }
}

TEST(BidirectionalPhotonGrid, GatherVisitsEachPhotonWithinTheRadiusOnce) {
    for (int count : {1, 2, 7, 20000}) expect_each_photon_within_the_radius_visited_once(count, 1);
}

TEST(BidirectionalPhotonGrid, GridOfSomePhotonsGathersThoseAlone) {
    for (int count : {2, 7, 20000}) expect_each_photon_within_the_radius_visited_once(count, 3);
}

}  // namespace
}  // namespace rayset::tracer
