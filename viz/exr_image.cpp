#include "viz/exr_image.h"

#include "core/error.h"
#include "viz/vtk_arrays.h"

#include <ImathBox.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>

#include <vtkPointData.h>

#include <algorithm>
#include <exception>

namespace rayset::viz {

std::vector<std::string> exr_channels(const std::string& path) {
    try {
        Imf::InputFile file(path.c_str());
        std::vector<std::string> names;
        for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c)
            names.push_back(c.name());
        return names;
    } catch (const std::exception& e) {
        fail(path, std::string("cannot read as OpenEXR: ") + e.what());
    }
}

ExrLayer read_exr_layer(const std::string& path, const std::string& layer) {
    const std::vector<std::string> names = exr_channels(path);
    auto has = [&](const std::string& n) {
        return std::find(names.begin(), names.end(), n) != names.end();
    };
    const std::string prefix = layer.empty() || layer == "Y" ? "" : layer + ".";
    std::vector<std::pair<std::string, float>> weighted;  // channels and their luminance weights
    if (!layer.empty() && has(layer)) {
        weighted = {{layer, 1.0f}};
    } else if (has(prefix + "Y")) {
        weighted = {{prefix + "Y", 1.0f}};
    } else if (has(prefix + "R") && has(prefix + "G") && has(prefix + "B")) {
        weighted = {{prefix + "R", 0.2126f}, {prefix + "G", 0.7152f}, {prefix + "B", 0.0722f}};
    } else {
        std::string list;
        for (const auto& n : names) list += " " + n;
        fail(path, "no channel or layer '" + layer + "' (channels:" + list + ")");
    }

    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
        std::vector<std::vector<float>> planes(weighted.size(),
                                               std::vector<float>(size_t(width) * height));
        Imf::FrameBuffer buffer;
        for (size_t c = 0; c < weighted.size(); ++c) {
            // The frame buffer is addressed by absolute pixel coordinates of the data window.
            char* base = reinterpret_cast<char*>(planes[c].data() - window.min.x -
                                                 size_t(window.min.y) * width);
            buffer.insert(weighted[c].first.c_str(), Imf::Slice(Imf::FLOAT, base, sizeof(float),
                                                                sizeof(float) * size_t(width)));
        }
        file.setFrameBuffer(buffer);
        file.readPixels(window.min.y, window.max.y);

        ExrLayer out;
        out.image = vtkSmartPointer<vtkImageData>::New();
        out.image->SetDimensions(width, height, 1);
        auto luminance = named_floats("luminance");
        luminance->SetNumberOfTuples(vtkIdType(width) * height);
        // EXR rows run top to bottom, VTK's bottom to top.
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                float value = 0;
                for (size_t c = 0; c < weighted.size(); ++c)
                    value += weighted[c].second * planes[c][size_t(y) * width + x];
                luminance->SetValue(vtkIdType(height - 1 - y) * width + x, value);
            }
        out.image->GetPointData()->SetScalars(luminance);
        const auto* units = file.header().findTypedAttribute<Imf::StringAttribute>("units");
        out.unit = units ? units->value() : "cd/m^2";
        out.channel =
            weighted.size() == 1 ? weighted[0].first : prefix + "R," + prefix + "G," + prefix + "B";
        set_field_string(out.image, "unit", out.unit);
        set_field_string(out.image, "channel", out.channel);
        return out;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        fail(path, std::string("cannot read as OpenEXR: ") + e.what());
    }
}

}  // namespace rayset::viz
