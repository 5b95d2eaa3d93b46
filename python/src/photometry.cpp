// Photometry: IES LM-63 and EULUMDAT files as Photometry objects with numpy angles and candela
// tables, and the far field of a ray file by the function `rayconv farfield` uses.
#include "arrays.h"

#include <nanobind/stl/filesystem.h>
#include <nanobind/stl/map.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "converters/photometry/farfield.h"
#include "converters/photometry/photometry.h"
#include "converters/rays/ray_stream.h"
#include "core/error.h"

namespace rayset::python {

namespace {

// A table indexed [h * vertical + v] as a (horizontal, vertical) array.
Array<double> table(const std::vector<double>& values, size_t horizontal, size_t vertical) {
    if (values.size() != horizontal * vertical)
        throw Error(fmt::format("a table of {} values for {} x {} angles", values.size(),
                                horizontal, vertical));
    NewArray<double> out({horizontal, vertical});
    std::copy(values.begin(), values.end(), out.data);
    return out.array;
}

Array<double> candela_of(const Photometry& p) {
    return table(p.candela, p.horizontal_deg.size(), p.vertical_deg.size());
}

// Any array-like (lists too), through numpy.
void set_candela(Photometry& p, nb::handle value) {
    using Table = nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
    nb::object array = nb::module_::import_("numpy").attr("ascontiguousarray")(
        value, nb::arg("dtype") = "float64");
    if (nb::cast<size_t>(array.attr("ndim")) != 2)
        throw nb::value_error("candela must be a (horizontal, vertical) array");
    const Table c = nb::cast<Table>(array);
    if (c.shape(0) != p.horizontal_deg.size() || c.shape(1) != p.vertical_deg.size())
        throw nb::value_error(fmt::format("candela must be (horizontal, vertical) = ({}, {}) "
                                          "values: set the angles first; got ({}, {})",
                                          p.horizontal_deg.size(), p.vertical_deg.size(),
                                          c.shape(0), c.shape(1))
                                  .c_str());
    p.candela.assign(c.data(), c.data() + c.size());
}

PhotometryFormat photometry_format(const std::string& path, const std::optional<std::string>& f) {
    std::string name = f ? *f : path.substr(std::min(path.size(), path.rfind('.') + 1));
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (name == "ies") return PhotometryFormat::ies;
    if (name == "ldt" || name == "eulumdat") return PhotometryFormat::eulumdat;
    throw nb::value_error(
        fmt::format("{}: name the format ('ies' or 'ldt'): the name ends neither in .ies nor .ldt",
                    path)
            .c_str());
}

const char* type_name(PhotometricType t) {
    return t == PhotometricType::A ? "A" : t == PhotometricType::B ? "B" : "C";
}

FarField far_field_of(const Path& path, double c_step, double gamma_step, const std::string& axis,
                      bool radiometric, const std::string& smoothing, bool round,
                      const std::optional<std::string>& format, const std::string& trust,
                      bool normalise) {
    FarFieldOptions o;
    o.c_step_deg = c_step, o.gamma_step_deg = gamma_step;
    if (axis != "+z" && axis != "-z") throw nb::value_error("axis must be '+z' or '-z'");
    o.axis = axis == "-z" ? PolarAxis::minus_z : PolarAxis::plus_z;
    o.quantity = radiometric ? FarFieldQuantity::radiometric : FarFieldQuantity::photometric;
    parse_smoothing(smoothing, o);
    RayReadOptions r;
    if (format) {
        auto f = ray_format_from_name(*format);
        if (!f) throw nb::value_error(fmt::format("unknown ray format '{}'", *format).c_str());
        r.format = *f;
    }
    if (trust == "header") r.flux_policy = FluxPolicy::stated;
    if (trust == "rays") r.flux_policy = FluxPolicy::rays;
    r.normalise_directions = normalise;
    nb::gil_scoped_release release;
    auto reader = open_rays(path.string(), r);
    FarField far = far_field(*reader, o);
    if (round) round_to_uncertainty(far);
    return far;
}

void bind_photometry_class(nb::module_& m) {
    nb::class_<Photometry>(
        m, "Photometry",
        "Far-field photometry as IES LM-63 and EULUMDAT hold it: intensity (cd) on a grid of "
        "horizontal (C) and vertical (gamma) angles of one photometric type. Arrays are copies: "
        "assign a whole array to change one.")
        .def(nb::init<>())
        .def_prop_rw(
            "type", [](const Photometry& p) { return std::string(type_name(p.type)); },
            [](Photometry& p, const std::string& t) {
                if (t != "A" && t != "B" && t != "C")
                    throw nb::value_error("type must be 'A', 'B' or 'C'");
                p.type = t == "A"   ? PhotometricType::A
                         : t == "B" ? PhotometricType::B
                                    : PhotometricType::C;
            },
            "Photometric type: 'C' (gamma from nadir, C planes), 'B' or 'A'.")
        .def_prop_rw(
            "vertical_deg", [](const Photometry& p) { return object(to_array(p.vertical_deg)); },
            [](Photometry& p, const std::vector<double>& v) { p.vertical_deg = v; },
            "Vertical angles, degrees, ascending.")
        .def_prop_rw(
            "horizontal_deg",
            [](const Photometry& p) { return object(to_array(p.horizontal_deg)); },
            [](Photometry& p, const std::vector<double>& v) { p.horizontal_deg = v; },
            "Horizontal angles, degrees, ascending (possibly only a symmetric part).")
        .def_prop_rw(
            "candela", [](const Photometry& p) { return object(candela_of(p)); }, &set_candela,
            "Intensity, cd, as a (horizontal, vertical) array.")
        .def_rw("lamp_count", &Photometry::lamp_count, "Number of lamps.")
        .def_rw("rated_lumens", &Photometry::rated_lumens,
                "Rated lamp flux, lm; not above zero for absolute photometry.")
        .def_rw("input_watts", &Photometry::input_watts, "Input power, W.")
        .def_rw("ballast_factor", &Photometry::ballast_factor, "Ballast factor.")
        .def_rw("width_m", &Photometry::width_m, "Luminous opening across C90-C270, m.")
        .def_rw("length_m", &Photometry::length_m, "Luminous opening along C0-C180, m.")
        .def_rw("height_m", &Photometry::height_m, "Luminous opening height, m.")
        .def_rw("round", &Photometry::round, "Whether the opening is round.")
        .def_rw("keywords", &Photometry::keywords,
                "Descriptive text: IES keywords and the EULUMDAT header lines (a copy).")
        .def(
            "intensity",
            [](const Photometry& p, const Values& horizontal, const Values& vertical) {
                check_rows(horizontal.shape(0), vertical.shape(0), "vertical");
                NewArray<double> out({horizontal.shape(0)});
                for (size_t i = 0; i < horizontal.shape(0); ++i)
                    out.data[i] = p.intensity(horizontal(i), vertical(i));
                return out.array;
            },
            nb::arg("horizontal_deg"), nb::arg("vertical_deg"),
            "Intensity (cd) toward each (horizontal, vertical) pair of angles in degrees, over "
            "the whole sphere: symmetry unfolded, bilinear between grid angles.")
        .def("total_flux", &Photometry::total_flux,
             "Luminous flux, lm: the intensity integrated over the sphere.")
        .def("max_candela", &Photometry::max_candela, "The largest value of the table, cd.");
}

void bind_photometry_files(nb::module_& m) {
    m.def(
        "read_photometry",
        [](const Path& path) {
            nb::gil_scoped_release release;
            return read_photometry(path.string());
        },
        nb::arg("path"), "Reads an IES LM-63 or EULUMDAT file (told apart by content).");
    m.def(
        "write_photometry",
        [](const Path& path, const Photometry& p, const std::optional<std::string>& f) {
            const PhotometryFormat format = photometry_format(path.string(), f);
            nb::gil_scoped_release release;
            write_photometry(path.string(), p, format);
        },
        nb::arg("path"), nb::arg("photometry"), nb::arg("format") = nb::none(),
        "Writes IES LM-63 ('ies') or EULUMDAT ('ldt'); the format follows the name's extension "
        "unless given.");
    m.def(
        "detect_photometry_format",
        [](const Path& path) {
            return std::string(
                detect_photometry_format(path.string()) == PhotometryFormat::ies ? "ies" : "ldt");
        },
        nb::arg("path"), "'ies' or 'ldt', from the file's content.");
}

void bind_far_field(nb::module_& m) {
    nb::class_<FarField>(m, "FarField",
                         "The far field of a ray file: type C photometry and, per cell, its "
                         "flux, solid angle, variance and kernel bandwidth.")
        .def_ro("photometry", &FarField::photometry,
                "Type C photometry, C 0..360 (360 repeats 0), gamma 0..180; W/sr when "
                "radiometric.")
        .def_prop_ro(
            "flux",
            [](const FarField& f) {
                return object(table(f.flux, f.photometry.horizontal_deg.size(),
                                    f.photometry.vertical_deg.size()));
            },
            "Flux of each cell, lm or W, (C, gamma).")
        .def_prop_ro(
            "solid_angle",
            [](const FarField& f) {
                return object(table(f.solid_angle, f.photometry.horizontal_deg.size(),
                                    f.photometry.vertical_deg.size()));
            },
            "Solid angle of each cell, sr, (C, gamma).")
        .def_prop_ro(
            "variance",
            [](const FarField& f) {
                return object(table(f.variance, f.photometry.horizontal_deg.size(),
                                    f.photometry.vertical_deg.size()));
            },
            "Estimated variance of each intensity (its standard error squared), (C, gamma).")
        .def_prop_ro(
            "sigma_deg",
            [](const FarField& f) {
                if (f.sigma_deg.empty()) return object(to_array(f.sigma_deg));
                return object(table(f.sigma_deg, f.photometry.horizontal_deg.size(),
                                    f.photometry.vertical_deg.size()));
            },
            "Smoothed: the kernel bandwidth of each value, degrees (C, gamma); else empty.")
        .def_ro("method", &FarField::method, "How the values were made (keyword _SMOOTHING).")
        .def_ro("flux_scale", &FarField::flux_scale,
                "Smoothed: the factor that keeps the rays' flux.")
        .def_ro("rays", &FarField::rays, "Rays read.")
        .def_ro("total_flux", &FarField::total_flux, "Sum of the cells = sum of the rays.")
        .def_ro("max_intensity", &FarField::max_intensity, "Largest intensity.")
        .def_ro("max_c_deg", &FarField::max_c_deg, "C angle of the largest intensity.")
        .def_ro("max_gamma_deg", &FarField::max_gamma_deg, "Gamma of the largest intensity.")
        .def_prop_ro("written_flux", &written_flux,
                     "Sum of intensity x solid angle over the cells (after rounding: what a "
                     "file written from it holds).");

    m.def("far_field", &far_field_of, nb::arg("path"), nb::arg("c_step") = 5.0,
          nb::arg("gamma_step") = 2.5, nb::arg("axis") = "+z", nb::arg("radiometric") = false,
          nb::arg("smoothing") = "auto", nb::arg("round") = false, nb::arg("format") = nb::none(),
          nb::arg("trust") = "", nb::arg("normalise") = false,
          "The far field of a ray file, as `rayconv farfield` computes it: smoothing 'auto' "
          "(kernel density, local fits, bandwidth from the rays), 'none' (the histogram) or a "
          "bandwidth in degrees given as text; round=True rounds the intensities to the digits "
          "their standard errors support, as rayconv does before writing.");
}

}  // namespace

void bind_photometry(nb::module_& m) {
    bind_photometry_class(m);
    bind_photometry_files(m);
    bind_far_field(m);
}

}  // namespace rayset::python
