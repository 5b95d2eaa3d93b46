// The bundled example scenes (examples/): they parse, and the paper's box shows its 39 LED
// chips as 39 separate spots in the direct-visibility layer (issue 6: "the LED chips visibly
// distinct"), with the colours the chips were given.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "converters/analytic/synth.h"
#include "support/test_support.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
namespace {

const std::string kExamples = std::string(RAYSET_SOURCE_DIR) + "/examples/";

// 4-connected groups of lit pixels, with the summed colour of each.
std::vector<Rgb> lit_components(const Film& film) {
    const int w = film.nx(), h = film.ny();
    std::vector<int> label(size_t(w) * h, -1);
    std::vector<Rgb> components;
    for (int start = 0; start < w * h; ++start) {
        if (label[size_t(start)] >= 0 || !(max_component(film.mean(start % w, start / w)) > 0))
            continue;
        Rgb sum;
        std::vector<int> stack{start};
        label[size_t(start)] = int(components.size());
        while (!stack.empty()) {
            const int p = stack.back();
            stack.pop_back();
            const int x = p % w, y = p / w;
            sum += film.mean(x, y);
            const int neighbours[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
            for (const auto& n : neighbours) {
                if (n[0] < 0 || n[1] < 0 || n[0] >= w || n[1] >= h) continue;
                const int q = n[1] * w + n[0];
                if (label[size_t(q)] >= 0 || !(max_component(film.mean(n[0], n[1])) > 0)) continue;
                label[size_t(q)] = int(components.size());
                stack.push_back(q);
            }
        }
        components.push_back(sum);
    }
    return components;
}

TEST(Examples, LedBoxShowsThe39ChipsApartInTheirColours) {
    // The cluster as scripts/example.sh makes it, with fewer rays (2e5; the model's lattice
    // cells are then 0.33 mm against chips of 1 mm and gaps of about 1 mm).
    test::ScratchDir scratch;
    const auto cluster = make_source("cluster", {{"rings", "1,6,12,20"},
                                                 {"chip", "1"},
                                                 {"pitch", "2"},
                                                 {"flux", "1"},
                                                 {"wavelength", "630,530,460"}});
    {
        auto out = create_rays(scratch.file("cluster.tm25ray"), RayFormat::tm25,
                               synth_header(*cluster, 200000, 1));
        synthesize(*cluster, 200000, 1, *out);
    }
    ParseOptions options;
    options.include_paths = {scratch.path().string()};
    const RenderScene scene(parse_scene_file(kExamples + "led_box.pov", options));
    RenderSettings settings;
    settings.width = 640, settings.height = 480, settings.passes = 1, settings.seed = 1;
    settings.photons_per_pass = 1000;  // only the direct-visibility layer is looked at
    const RenderResult r = render(scene, settings);
    std::vector<Rgb> chips = lit_components(r.layers[0].film);
    // The chips and, through the mirror ball, their reflection: the 39 largest spots are the
    // chips seen directly (the ball's image is a few pixels).
    std::sort(chips.begin(), chips.end(),
              [](Rgb a, Rgb b) { return luminance_weight(a) > luminance_weight(b); });
    ASSERT_GE(chips.size(), 39u);
    int red = 0, green = 0, blue = 0;
    for (size_t k = 0; k < 39; ++k) {
        const Rgb c = chips[k];
        red += c.red > c.green && c.red > c.blue;
        green += c.green > c.red && c.green > c.blue;
        blue += c.blue > c.red && c.blue > c.green;
    }
    // rings 1 + 6 + 12 + 20 with the three wavelengths in turn: 13 chips of each colour.
    EXPECT_EQ(red, 13);
    EXPECT_EQ(green, 13);
    EXPECT_EQ(blue, 13);
    std::printf("direct visibility: %zu lit spots; the 39 brightest: %d red, %d green, %d blue\n",
                chips.size(), red, green, blue);
}

TEST(Examples, OsramDomeParses) {
    RAYSET_REQUIRE_SHARED_DATA();
    ParseOptions options;
    options.include_paths = {test::shared_data("rayfiles")};
    const SceneDescription scene = parse_scene_file(kExamples + "osram_dome.pov", options);
    EXPECT_EQ(scene.ray_sources.size(), 1u);
    EXPECT_EQ(scene.receivers.size(), 1u);
}

}  // namespace
}  // namespace rayset::tracer
