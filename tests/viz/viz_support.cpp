#include "viz/viz_support.h"

#include "lightmodel/model_file.h"

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <mutex>
#include <set>

namespace rayset::test {

const std::string& cluster_model_file() {
    static std::mutex mutex;
    static ScratchDir scratch;
    static std::string path;
    std::lock_guard<std::mutex> lock(mutex);
    if (path.empty()) {
        const BuiltSource& cluster = built_source("cluster");
        path = scratch.file("cluster.vdb");
        lightmodel::write_model(*cluster.model, path);
    }
    return path;
}

PngStatistics png_statistics(const std::string& path, const double region[4]) {
    auto reader = vtkSmartPointer<vtkPNGReader>::New();
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    PngStatistics s;
    int dims[3];
    image->GetDimensions(dims);
    s.width = dims[0], s.height = dims[1];
    const int channels = image->GetNumberOfScalarComponents();
    auto pixel = [&](int x, int y) {
        const auto* p = static_cast<const unsigned char*>(image->GetScalarPointer(x, y, 0));
        return (uint32_t(p[0]) << 16) | (uint32_t(p[channels > 1 ? 1 : 0]) << 8) |
               p[channels > 2 ? 2 : 0];
    };
    const uint32_t background = pixel(0, s.height - 1);
    std::set<uint32_t> colours;
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const uint32_t c = pixel(x, y);
            if (c == background) continue;
            ++s.foreground;
            const double fx = (x + 0.5) / s.width, fy = (y + 0.5) / s.height;
            if (fx >= region[0] && fx <= region[1] && fy >= region[2] && fy <= region[3]) {
                ++s.region_foreground;
                colours.insert(c);
            }
        }
    s.region_colours = int(colours.size());
    return s;
}

}  // namespace rayset::test
