#include "viz/export.h"

#include "converters/rays/io.h"
#include "core/error.h"
#include "viz/diagram_surface.h"

#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <fmt/format.h>
#include <filesystem>
#include <fstream>

namespace rayset::viz {

namespace fs = std::filesystem;

void write_dataset(vtkDataObject* data, const std::string& path) {
    write_atomically(path, [&](const std::string& temporary) {
        if (auto* image = vtkImageData::SafeDownCast(data)) {
            auto writer = vtkSmartPointer<vtkXMLImageDataWriter>::New();
            writer->SetInputData(image);
            writer->SetFileName(temporary.c_str());
            return writer->Write() == 1;
        }
        if (auto* poly = vtkPolyData::SafeDownCast(data)) {
            auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
            writer->SetInputData(poly);
            writer->SetFileName(temporary.c_str());
            return writer->Write() == 1;
        }
        return false;
    });
}

namespace {

// The collection ParaView opens in one go: a multiblock file whose blocks are the files beside
// it (the format vtkXMLMultiBlockDataWriter writes, without copying the data again).
void write_collection(const std::string& path,
                      const std::vector<std::pair<std::string, std::string>>& blocks) {
    write_atomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary);
        out << "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" "
               "byte_order=\"LittleEndian\">\n"
               "  <vtkMultiBlockDataSet>\n";
        for (size_t i = 0; i < blocks.size(); ++i)
            out << fmt::format("    <DataSet index=\"{}\" name=\"{}\" file=\"{}\"/>\n", i,
                               blocks[i].first, blocks[i].second);
        out << "  </vtkMultiBlockDataSet>\n</VTKFile>\n";
        return bool(out.flush());
    });
}

}  // namespace

std::vector<std::string> export_input(Input& input, const ViewOptions& options,
                                      const std::string& directory) {
    std::error_code error;
    fs::create_directories(directory, error);
    if (error) throw Error(directory + ": cannot create the folder: " + error.message());
    std::vector<std::pair<std::string, std::string>> blocks;  // name, file name
    std::vector<std::string> written;
    auto save = [&](const std::string& name, const std::string& extension, vtkDataObject* data) {
        const std::string file = name + extension;
        write_dataset(data, (fs::path(directory) / file).string());
        blocks.emplace_back(name, file);
        written.push_back((fs::path(directory) / file).string());
    };
    switch (input.kind()) {
        case InputKind::model: {
            save("density", ".vti", input.data(View::density, options));
            save("flux", ".vti", input.data(View::flux, options));
            save("spheres", ".vtp", input.data(View::spheres, options));
            const auto& model = input.model();
            for (size_t k = 0; k < model.diagrams.size(); ++k) {
                if (model.diagrams[k].empty()) continue;
                const auto& c = model.diagram_cells[k];
                save(fmt::format("diagram_{}_{}_{}", c[0], c[1], c[2]), ".vtp",
                     diagram_surface(model, c));
            }
            break;
        }
        case InputKind::rays:
            save("rays", ".vtp", input.data(View::rays, options));
            save("farfield", ".vtp", input.data(View::farfield, options));
            save("polar", ".vtp", input.data(View::polar, options));
            break;
        case InputKind::photometry:
            save("farfield", ".vtp", input.data(View::farfield, options));
            save("polar", ".vtp", input.data(View::polar, options));
            break;
        case InputKind::image: save("image", ".vti", input.data(View::image, options)); break;
    }
    const std::string collection =
        (fs::path(directory) / (fs::path(input.path()).stem().string() + ".vtm")).string();
    write_collection(collection, blocks);
    written.push_back(collection);
    return written;
}

}  // namespace rayset::viz
