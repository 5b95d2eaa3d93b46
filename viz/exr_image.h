// One layer of an OpenEXR image (the tracer's output) as a VTK image of luminance, for a
// colour-mapped view with a scale bar.
#pragma once

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace rayset::viz {

struct ExrLayer {
    vtkSmartPointer<vtkImageData>
        image;            // point data "luminance", one point per pixel, row 0 at the bottom
    std::string unit;     // the header's "units" string attribute, else "cd/m^2"
    std::string channel;  // what was read: a channel name, or "R,G,B"
};

// `layer`: a channel of that name ("Y", "illuminance"), or the layer's Y channel ("layer.Y"),
// or its R, G, B channels combined into luminance with the Rec. 709 weights
// 0.2126 R + 0.7152 G + 0.0722 B. Throws rayset::Error listing the channels when none fits.
ExrLayer read_exr_layer(const std::string& path, const std::string& layer = "Y");
// Channel names of the file, in the file's order.
std::vector<std::string> exr_channels(const std::string& path);

}  // namespace rayset::viz
