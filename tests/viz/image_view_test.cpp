// EXR image view: a layer is read with the right values, orientation and unit, and renders
// with its scale bar.
#include <gtest/gtest.h>

#include "support/test_support.h"
#include "viz/scene.h"
#include "viz/viz_support.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <vector>

namespace {

using namespace rayset;

// W x H image with channels R, G, B (value at (x, y), y = 0 the top row) and a "units" attribute.
void write_rgb_exr(const std::string& path, int w, int h, const char* units) {
    Imf::Header header(w, h);
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    header.insert("units", Imf::StringAttribute(units));
    std::vector<float> r(size_t(w) * h), g(r.size()), b(r.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            r[size_t(y) * w + x] = float(x);
            g[size_t(y) * w + x] = float(10 * y);
            b[size_t(y) * w + x] = 100;
        }
    Imf::FrameBuffer buffer;
    buffer.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(r.data()), sizeof(float),
                                  sizeof(float) * w));
    buffer.insert("G", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(g.data()), sizeof(float),
                                  sizeof(float) * w));
    buffer.insert("B", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(b.data()), sizeof(float),
                                  sizeof(float) * w));
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(buffer);
    file.writePixels(h);
}

}  // namespace

TEST(ImageView, LuminanceOfAnRgbLayerUpsideUp) {
    test::ScratchDir dir;
    const int w = 64, h = 48;
    write_rgb_exr(dir.file("render.exr"), w, h, "cd/m^2");
    const viz::ExrLayer layer = viz::read_exr_layer(dir.file("render.exr"));
    EXPECT_EQ(layer.unit, "cd/m^2");
    EXPECT_EQ(layer.channel, "R,G,B");
    int dims[3];
    layer.image->GetDimensions(dims);
    ASSERT_EQ(dims[0], w);
    ASSERT_EQ(dims[1], h);
    vtkDataArray* y = layer.image->GetPointData()->GetArray("luminance");
    // VTK row 0 is the bottom, EXR row 0 the top: VTK (x, j) holds EXR row h - 1 - j.
    for (int j : {0, 17, h - 1})
        for (int x : {0, 5, w - 1}) {
            const double expected = 0.2126 * x + 0.7152 * 10 * (h - 1 - j) + 0.0722 * 100;
            EXPECT_NEAR(y->GetComponent(vtkIdType(j) * w + x, 0), expected, 1e-4 * expected);
        }
    EXPECT_THROW(viz::read_exr_layer(dir.file("render.exr"), "albedo"), rayset::Error);
}

TEST(ImageView, RendersWithItsScaleBar) {
    test::ScratchDir dir;
    write_rgb_exr(dir.file("render.exr"), 64, 48, "lux");
    viz::Input input(dir.file("render.exr"));
    ASSERT_EQ(input.kind(), viz::InputKind::image);
    viz::SceneOptions options;
    options.width = 640, options.height = 480, options.offscreen = true;
    viz::Scene scene = viz::build_scene(input, nullptr, viz::View::image, {}, options);
    viz::write_png(scene, dir.file("image.png"));
    const double bar[4] = {0.86, 0.98, 0.1, 0.9};
    const test::PngStatistics s = test::png_statistics(dir.file("image.png"), bar);
    EXPECT_GT(s.foreground, 0.2 * s.width * s.height);  // the image fills much of the window
    EXPECT_GT(s.region_colours, 50);                    // the bar's gradient
}
