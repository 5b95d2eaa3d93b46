// Writing the image, preview and receiver maps through StagedFiles.
#include "tracer/film/render_output.h"

#include <cstdio>

#include <fmt/format.h>

#include "core/error.h"
#include "tracer/film/image_writers.h"
#include "tracer/film/staged_files.h"

namespace rayset::tracer {

namespace {

std::vector<ExrChannel> grid_channels(const SampleGrid& grid, double photometric_scale,
                                      bool with_error) {
    std::vector<ExrChannel> c{{"R", {}}, {"G", {}}, {"B", {}}, {"Y", {}}};
    if (with_error) c.push_back({"Y_stderr", {}});
    for (int y = 0; y < grid.ny(); ++y)
        for (int x = 0; x < grid.nx(); ++x) {
            const Rgb m = grid.mean(x, y);
            c[0].values.push_back(float(m.red));
            c[1].values.push_back(float(m.green));
            c[2].values.push_back(float(m.blue));
            c[3].values.push_back(float(photometric(m) * photometric_scale));
            if (with_error)
                c[4].values.push_back(
                    float(grid.photometric_standard_error(x, y) * photometric_scale));
        }
    return c;
}

void write_text(const std::string& path, const std::string& text) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw Error(fmt::format("{}: cannot create the file", path));
    const bool ok = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    if (std::fclose(file) != 0 || !ok) throw Error(fmt::format("{}: cannot write the file", path));
}

}  // namespace

std::string receiver_csv(const ReceiverMap& map) {
    std::string text =
        "i,j,x,y,z,illuminance_lx,standard_error_lx,irradiance_red_W_m2,irradiance_green_W_m2,"
        "irradiance_blue_W_m2\n";
    const SampleGrid& g = map.irradiance;
    for (int j = 0; j < g.ny(); ++j)
        for (int i = 0; i < g.nx(); ++i) {
            const Vec3 p = map.cell_centre(i, j);
            const Rgb e = g.mean(i, j);
            text += fmt::format("{},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n",
                                i, j, p.x, p.y, p.z, g.photometric_mean(i, j),
                                g.photometric_standard_error(i, j), e.red, e.green, e.blue);
        }
    return text;
}

std::vector<std::string> write_render_outputs(const Film* film,
                                              const std::vector<ReceiverMap>& receivers,
                                              const OutputRequest& request) {
    StagedFiles files;
    if (film && !request.exr.empty()) {
        write_exr(files.stage(request.exr), film->nx(), film->ny(), grid_channels(*film, 1, false),
                  {{"rayset_units",
                    "R,G,B: radiance W/(m^2 sr) per linear-sRGB channel; Y: luminance cd/m^2 = "
                    "683 * (0.2126 R + 0.7152 G + 0.0722 B)"},
                   {"rayset_samples_per_pixel", std::to_string(film->samples())}});
        if (!request.png.empty())
            write_png(files.stage(request.png), film->nx(), film->ny(),
                      tone_map_srgb(*film, request.exposure));
    }
    for (const ReceiverMap& map : receivers) {
        const std::string base = request.receiver_prefix + "." + map.receiver.name;
        write_exr(
            files.stage(base + ".exr"), map.irradiance.nx(), map.irradiance.ny(),
            grid_channels(map.irradiance, 1, true),
            {{"rayset_units",
              "R,G,B: irradiance W/m^2 per linear-sRGB channel; Y: illuminance lx; "
              "Y_stderr: standard error of Y; pixel (i, j): cell i along edge1, j along edge2"},
             {"rayset_samples_per_cell", std::to_string(map.irradiance.samples())}});
        write_text(files.stage(base + ".csv"), receiver_csv(map));
    }
    files.commit();
    return files.targets();
}

}  // namespace rayset::tracer
