// Images laid on space (image_mapping.h).
#include "tracer/scene_language/image_mapping.h"

#include <algorithm>
#include <cmath>

#include "core/geometry.h"

namespace rayset::tracer {
namespace {

double fraction(double v) { return v - std::floor(v); }

// The angle of (x, z) from +x toward +z, in turns [0, 1).
double turns_about_y(double x, double z) {
    if (x == 0 && z == 0) return 0;
    return fraction(std::atan2(z, x) / (2 * kPi));
}

// The pixels a lookup blends, with their weights (rows from the top).
struct Texels {
    int count = 0;
    int column[4] = {}, row[4] = {};
    double weight[4] = {};
    void add(int c, int r, double w) {
        column[count] = c, row[count] = r, weight[count] = w;
        ++count;
    }
};

// Pixel index `i` of `n` along one axis: wrapped round a repeated image, held at its edge
// with `once`.
int pixel_index(int i, int n, bool once) {
    if (once) return i < 0 ? 0 : (i >= n ? n - 1 : i);
    const int r = i % n;
    return r < 0 ? r + n : r;
}

Texels texels_at(const ImageMap& image, int width, int height, double u, double v) {
    Texels texels;
    auto add = [&](int column, int row_from_bottom, double weight) {
        texels.add(pixel_index(column, width, image.once),
                   height - 1 - pixel_index(row_from_bottom, height, image.once), weight);
    };
    if (image.interpolate != 2 && image.interpolate != 4) {
        add(int(std::floor(u * width)), int(std::floor(v * height)), 1);
        return texels;
    }
    // Pixel centres sit at half-integer positions.
    const double x = u * width - 0.5, y = v * height - 0.5;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const double fx = x - x0, fy = y - y0;
    if (image.interpolate == 2) {
        add(x0, y0, (1 - fx) * (1 - fy));
        add(x0 + 1, y0, fx * (1 - fy));
        add(x0, y0 + 1, (1 - fx) * fy);
        add(x0 + 1, y0 + 1, fx * fy);
        return texels;
    }
    // Normalised distance: 1 / d^2, a point on a centre taking that pixel alone.
    double total = 0;
    for (int corner = 0; corner < 4; ++corner) {
        const double dx = (corner & 1) ? 1 - fx : fx, dy = (corner & 2) ? 1 - fy : fy;
        const double d2 = dx * dx + dy * dy;
        if (d2 < 1e-12) {
            texels = {};
            add(x0 + (corner & 1), y0 + (corner >> 1), 1);
            return texels;
        }
        add(x0 + (corner & 1), y0 + (corner >> 1), 1 / d2);
        total += 1 / d2;
    }
    for (int i = 0; i < 4; ++i) texels.weight[i] /= total;
    return texels;
}

// POV-Ray's grey of a pixel's numbers.
double grey(const float* rgba) { return 0.297 * rgba[0] + 0.589 * rgba[1] + 0.114 * rgba[2]; }

}  // namespace

bool image_coordinates(const ImageMap& image, Vec3 p, double& u, double& v) {
    switch (image.map_type) {
        case 1: {  // spherical: longitude from +x toward +z, latitude from the south pole
            const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
            u = turns_about_y(p.x, p.z);
            v = r == 0 ? 0.5 : 0.5 + std::asin(std::clamp(p.y / r, -1.0, 1.0)) / kPi;
            break;
        }
        case 2:  // cylindrical: round the y axis, up it
            u = turns_about_y(p.x, p.z);
            v = p.y;
            break;
        case 5:  // torus of major radius 1: round the y axis, round the tube from its inside
            u = turns_about_y(p.x, p.z);
            v = fraction(0.5 + turns_about_y(std::sqrt(p.x * p.x + p.z * p.z) - 1, p.y));
            break;
        default:  // planar
            u = p.x;
            v = p.y;
            break;
    }
    if (image.once) return u >= 0 && u < 1 && v >= 0 && v < 1;
    u = fraction(u), v = fraction(v);
    return true;
}

bool image_map_colour(const ImageMap& image, Vec3 p, Colour& colour) {
    if (!image.colours || !image.pixels) return false;
    double u = 0, v = 0;
    if (!image_coordinates(image, p, u, v)) {
        colour = {1, 1, 1, 0, 1};  // clear where a `once` image does not reach
        return true;
    }
    const Texels texels = texels_at(image, image.pixels->width, image.pixels->height, u, v);
    colour = {};
    for (int i = 0; i < texels.count; ++i) {
        const Colour& c = (*image.colours)[size_t(texels.row[i]) * size_t(image.pixels->width) +
                                           size_t(texels.column[i])];
        const double w = texels.weight[i];
        colour.red += w * c.red, colour.green += w * c.green, colour.blue += w * c.blue;
        colour.filter += w * c.filter, colour.transmit += w * c.transmit;
    }
    return true;
}

bool image_height(const ImageMap& image, Vec3 p, double& height) {
    if (!image.pixels) return false;
    double u = 0, v = 0;
    height = 0;
    if (!image_coordinates(image, p, u, v)) return true;
    const ImagePixels& pixels = *image.pixels;
    const Texels texels = texels_at(image, pixels.width, pixels.height, u, v);
    for (int i = 0; i < texels.count; ++i)
        height += texels.weight[i] * grey(pixels.pixel(texels.column[i], texels.row[i]));
    return true;
}

}  // namespace rayset::tracer
