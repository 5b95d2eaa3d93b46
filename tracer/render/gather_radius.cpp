// The progressive gather radius (see gather_radius.h).
#include "tracer/render/gather_radius.h"

#include <algorithm>
#include <cmath>

namespace rayset::tracer {

namespace {
constexpr double kAlpha = 2.0 / 3.0;
}

double shrunk_radius(double radius, int passes_done) {
    return radius * std::sqrt((passes_done + kAlpha) / (passes_done + 1));
}

double default_radius(std::vector<Vec3> points) {
    if (points.empty()) return 1;
    double squares = 0;
    for (double Vec3::*axis : {&Vec3::x, &Vec3::y, &Vec3::z}) {
        auto at = [&](double fraction) {
            const auto k = points.begin() + std::ptrdiff_t(fraction * double(points.size() - 1));
            std::nth_element(points.begin(), k, points.end(),
                             [axis](Vec3 a, Vec3 b) { return a.*axis < b.*axis; });
            return (*k).*axis;
        };
        const double low = at(0.05), high = at(0.95);
        squares += (high - low) * (high - low);
    }
    const double diagonal = std::sqrt(squares);
    return diagonal > 0 ? diagonal / 100 : 1;
}

void append_receiver_cells(const std::vector<ReceiverMap>& receivers, std::vector<Vec3>& points) {
    for (const ReceiverMap& map : receivers)
        for (int j = 0; j < map.receiver.ny; ++j)
            for (int i = 0; i < map.receiver.nx; ++i) points.push_back(map.cell_centre(i, j));
}

}  // namespace rayset::tracer
