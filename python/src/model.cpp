// Light-source models: build from a ray file, load, save, and the emitter interface
// (lightmodel/emitter.h) over arrays: one query per row, rows spread over TBB's threads without
// the GIL (each row's result depends on its inputs alone, so the split changes no value).
#include "arrays.h"

#include <nanobind/stl/filesystem.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <limits>
#include <memory>

#include "core/error.h"
#include "lightmodel/complex_source.h"
#include "lightmodel/model_build.h"
#include "lightmodel/model_file.h"

namespace rayset::python {

namespace {

using lightmodel::ComplexSource;
using lightmodel::diagram_smoothing_name;
using lightmodel::DiagramSmoothing;
using lightmodel::LightModel;
using lightmodel::ModelOptions;
using lightmodel::SpectralSelect;
using lightmodel::visit_model_options;

template <class F>
void each_row(size_t rows, const F& f) {
    nb::gil_scoped_release release;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rows, 256),
                      [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t i = r.begin(); i != r.end(); ++i) f(i);
                      });
}

SpectralSelect select_of(const std::string& quantity, int band) {
    SpectralSelect s;
    if (quantity == "luminous")
        s.quantity = SpectralSelect::luminous;
    else if (quantity != "flux")
        throw nb::value_error("quantity must be 'flux' (the model's flux unit) or 'luminous' (lm)");
    s.band = band;
    return s;
}

// The wavelengths of row i of an N x 4 array (nm) as a query whose values start at zero.
lightmodel::SpectralQuery query_of(const Randoms& wavelengths, size_t i) {
    lightmodel::SpectralQuery q;
    for (int k = 0; k < 4; ++k) q.nm[k] = wavelengths(i, k);
    return q;
}

void check_wavelengths(const std::optional<Randoms>& wavelengths, size_t rows) {
    if (!wavelengths) return;
    check_rows(rows, wavelengths->shape(0), "wavelengths");
    if (wavelengths->shape(1) != 4) throw nb::value_error("wavelengths must have 4 columns (nm)");
}

void put_rgb(double* out, size_t i, const Rgb& c) {
    out[3 * i] = c.red, out[3 * i + 1] = c.green, out[3 * i + 2] = c.blue;
}

// A keyword's value as the option's type: diagram_smoothing by its name, 'auto' or 'none'.
template <class T>
T option_value(nb::handle value, const char* name) {
    if constexpr (std::is_same_v<T, DiagramSmoothing>) {
        const std::string text = nb::cast<std::string>(value);
        for (DiagramSmoothing s : {DiagramSmoothing::automatic, DiagramSmoothing::none})
            if (text == diagram_smoothing_name(s)) return s;
        throw nb::value_error(fmt::format("{} must be 'auto' or 'none'", name).c_str());
    } else {
        return nb::cast<T>(value);
    }
}

// raymodel build's options by the names of visit_model_options, and those that do not decide
// what is built (spectral_bin_nm, threads, progress).
ModelOptions options_from(const nb::kwargs& kwargs) {
    ModelOptions o;
    for (auto [key, value] : kwargs) {
        const std::string k = nb::cast<std::string>(key);
        bool known = false;
        visit_model_options(o, [&](const char* name, auto& member, const char*) {
            if (k != name) return;
            member = option_value<std::decay_t<decltype(member)>>(value, name);
            known = true;
        });
        if (known) continue;
        if (k == "spectral_bin_nm")
            o.spectral_bin_nm = nb::cast<double>(value);
        else if (k == "threads")
            o.threads = nb::cast<int>(value);
        else if (k == "progress")
            o.progress = nb::cast<bool>(value);
        else
            throw nb::type_error(fmt::format("Model.build: unknown option '{}'", k).c_str());
    }
    return o;
}

nb::dict options_dict(const ModelOptions& o) {
    nb::dict d;
    visit_model_options(o, [&](const char* name, const auto& member, const char*) {
        if constexpr (std::is_same_v<std::decay_t<decltype(member)>, DiagramSmoothing>)
            d[name] = diagram_smoothing_name(member);
        else
            d[name] = member;
    });
    d["spectral_bin_nm"] = o.spectral_bin_nm;
    d["threads"] = o.threads;
    return d;
}

class Model {
public:
    // The source (with its Embree scene) stays where it was made: a Model moves as a pointer.
    explicit Model(LightModel model)
        : model_(std::make_shared<const LightModel>(std::move(model))),
          source_(std::make_shared<const ComplexSource>(model_)) {}

    static Model build(const Path& ray_path, const nb::kwargs& kwargs) {
        const ModelOptions options = options_from(kwargs);
        nb::gil_scoped_release release;
        return Model(lightmodel::build_model(ray_path.string(), options));
    }
    static Model load(const Path& path) {
        nb::gil_scoped_release release;
        return Model(lightmodel::read_model(path.string()));
    }
    void save(const Path& path) const {
        nb::gil_scoped_release release;
        lightmodel::write_model(*model_, path.string());
    }

    double phi(const std::string& quantity, int band) const {
        return source_->phi(select_of(quantity, band));
    }
    nb::tuple phi_colour() const {
        const Rgb c = source_->phi_colour();
        return nb::make_tuple(c.red, c.green, c.blue);
    }
    nb::tuple bounds() const {
        const lightmodel::Box b = source_->bounds();
        return nb::make_tuple(nb::make_tuple(b.lower.x, b.lower.y, b.lower.z),
                              nb::make_tuple(b.upper.x, b.upper.y, b.upper.z));
    }
    nb::dict info() const {
        const LightModel& m = *model_;
        nb::dict d;
        d["flux_unit"] = m.flux_unit;
        d["total_flux"] = m.total_flux();
        d["total_luminous"] = m.total_luminous();
        d["flux_cells"] = m.flux_cells.size();
        d["voxels"] = m.voxels.size();
        d["diagrams"] = m.diagrams.size();
        d["spheres"] = m.spheres.size();
        d["options"] = options_dict(m.options);
        nb::dict source;
        source["path"] = m.source.path;
        source["format"] = m.source.format;
        source["rays"] = m.source.rays;
        source["radiant"] = m.source.radiant;
        source["luminous"] = m.source.luminous;
        source["unit"] = m.source.unit;
        d["source"] = source;
        return d;
    }
    Array<float> spheres() const {
        NewArray<float> out({model_->spheres.size(), 4});
        for (size_t i = 0; i < model_->spheres.size(); ++i) {
            const auto& s = model_->spheres[i];
            float* row = out.data + 4 * i;
            row[0] = s.x, row[1] = s.y, row[2] = s.z, row[3] = s.r;
        }
        return out.array;
    }

    // One lattice as arrays: its frame as the file stores it and, per cell, what the model
    // keeps there; arrays indexed [z, y, x] (the frame's linear order, x fastest).
    nb::dict lattice(const std::string& name) const {
        const LightModel& m = *model_;
        const lightmodel::LatticeFrame* frame = name == "density"     ? &m.density_frame
                                                : name == "flux"      ? &m.flux_frame
                                                : name == "intensity" ? &m.intensity_frame
                                                                      : nullptr;
        if (!frame) throw nb::value_error("lattice must be 'density', 'flux' or 'intensity'");
        const auto& d = frame->dims();
        const std::vector<size_t> shape{size_t(d[2]), size_t(d[1]), size_t(d[0])};
        nb::dict out;
        out["dims"] = nb::make_tuple(d[0], d[1], d[2]);
        out["origin"] = nb::make_tuple(frame->origin().x, frame->origin().y, frame->origin().z);
        out["cell_size"] = frame->cell_size();
        out["resolution"] = frame->resolution();
        if (frame == &m.density_frame) {
            NewArray<float> density(shape);
            for (size_t v = 0; v < m.voxels.size(); ++v)
                density.data[frame->linear(m.voxels[v])] = m.voxel_density[v];
            out["density"] = density.array;
        } else if (frame == &m.flux_frame) {
            NewArray<double> flux(shape), luminous(shape);
            NewArray<int32_t> diagram(shape);
            std::fill(diagram.data, diagram.data + frame->cell_count(), -1);
            for (const auto& c : m.flux_cells) {
                const int64_t i = frame->linear(c.coord);
                flux.data[i] = c.flux, luminous.data[i] = c.luminous;
                diagram.data[i] = c.intensity_cell;
            }
            out["flux"] = flux.array, out["luminous"] = luminous.array;
            out["diagram"] = diagram.array;
        } else {
            NewArray<int32_t> diagram(shape);
            std::fill(diagram.data, diagram.data + frame->cell_count(), -1);
            for (size_t k = 0; k < m.diagram_cells.size(); ++k)
                diagram.data[frame->linear(m.diagram_cells[k])] = int32_t(k);
            out["diagram"] = diagram.array;
        }
        return out;
    }

    // The goniometric diagrams: per diagram its intensity cell, that cell's centre, the flux of
    // the flux cells using it and whether it holds any light.
    nb::dict diagrams() const {
        const LightModel& m = *model_;
        const size_t n = m.diagrams.size();
        NewArray<int32_t> cell({n, 3});
        NewArray<double> centre({n, 3}), flux({n});
        NewArray<bool> empty({n});
        for (size_t k = 0; k < n; ++k) {
            for (int a = 0; a < 3; ++a) cell.data[3 * k + a] = m.diagram_cells[k][a];
            put(centre.data, k, m.intensity_frame.cell_centre(m.diagram_cells[k]));
            empty.data[k] = m.diagrams[k].empty();
        }
        for (const auto& c : m.flux_cells)
            if (c.intensity_cell >= 0 && size_t(c.intensity_cell) < n)
                flux.data[c.intensity_cell] += c.flux;
        nb::dict d;
        d["cell"] = cell.array, d["centre"] = centre.array, d["flux"] = flux.array;
        d["empty"] = empty.array;
        return d;
    }

    // Far-field intensity of the light leaving diagram k's cell toward each direction:
    // Phi_k D_k(w), the radius of the diagram's polar surface.
    Array<double> diagram_intensity(int64_t k, const Points& direction) const {
        const LightModel& m = *model_;
        if (k < 0 || size_t(k) >= m.diagrams.size())
            throw nb::index_error(fmt::format("diagram {} of {}", k, m.diagrams.size()).c_str());
        double flux = 0;
        for (const auto& c : m.flux_cells)
            if (c.intensity_cell == k) flux += c.flux;
        const auto& diagram = m.diagrams[size_t(k)];
        const size_t n = direction.shape(0);
        NewArray<double> out({n});
        if (diagram.empty()) return out.array;
        each_row(n,
                 [&](size_t i) { out.data[i] = flux * diagram.pdf(python::point(direction, i)); });
        return out.array;
    }

    nb::dict intersect(const Points& origin, const Points& direction, double tmax) const {
        const size_t n = origin.shape(0);
        check_rows(n, direction.shape(0), "direction");
        check_points(origin, "origin"), check_directions(direction, "direction");
        NewArray<bool> hit({n});
        NewArray<double> t({n}), point({n, 3}), normal({n, 3});
        each_row(n, [&](size_t i) {
            lightmodel::EmitterHit h;
            hit.data[i] =
                source_->intersect(python::point(origin, i), python::point(direction, i), tmax, h);
            t.data[i] = hit.data[i] ? h.t : std::numeric_limits<double>::infinity();
            put(point.data, i, h.point), put(normal.data, i, h.normal);
        });
        nb::dict d;
        d["hit"] = hit.array, d["t"] = t.array, d["point"] = point.array;
        d["normal"] = normal.array;
        return d;
    }

    nb::dict L(const Points& origin, const Points& direction, double tmax,
               const std::string& quantity, int band,
               const std::optional<Randoms>& wavelengths) const {
        const SpectralSelect select = select_of(quantity, band);
        const size_t n = origin.shape(0);
        check_rows(n, direction.shape(0), "direction");
        check_points(origin, "origin"), check_directions(direction, "direction");
        check_wavelengths(wavelengths, n);
        NewArray<double> radiance({n}), colour({n, 3}), spectral({wavelengths ? n : 0, 4});
        NewArray<bool> hit({n});
        each_row(n, [&](size_t i) {
            const Vec3 o = python::point(origin, i), w = python::point(direction, i);
            lightmodel::EmitterHit h;
            hit.data[i] = source_->intersect(o, w, tmax, h);
            if (!hit.data[i]) return;
            radiance.data[i] = source_->L(o, w, h, select);
            put_rgb(colour.data, i, source_->L_colour(o, w, h));
            if (!wavelengths) return;
            lightmodel::SpectralQuery q = query_of(*wavelengths, i);
            source_->L_spectral(o, w, h, q);
            std::copy(q.value, q.value + 4, spectral.data + 4 * i);
        });
        nb::dict d;
        d["L"] = radiance.array, d["colour"] = colour.array, d["hit"] = hit.array;
        if (wavelengths) d["spectral"] = spectral.array;
        return d;
    }

    nb::dict sample_Li(const Points& ref, const Randoms& u, const std::string& quantity, int band,
                       const std::optional<Randoms>& wavelengths) const {
        const SpectralSelect select = select_of(quantity, band);
        const size_t n = ref.shape(0);
        check_rows(n, u.shape(0), "u");
        if (u.shape(1) != 5) throw nb::value_error("u must have 5 columns (cell, voxel, point)");
        check_points(ref, "ref"), check_uniforms(u, "u");
        check_wavelengths(wavelengths, n);
        NewArray<bool> valid({n});
        NewArray<double> wi({n, 3}), distance({n}), Li({n}), pdf({n}), colour({n, 3}),
            spectral({wavelengths ? n : 0, 4});
        each_row(n, [&](size_t i) {
            const double* r = u.data() + 5 * i;
            lightmodel::SpectralQuery q;
            if (wavelengths) q = query_of(*wavelengths, i);
            const auto s = source_->sample_Li(python::point(ref, i), r[0], r[1], {r[2], r[3], r[4]},
                                              select, wavelengths ? &q : nullptr);
            valid.data[i] = bool(s);
            if (!s) return;
            put(wi.data, i, s->wi);
            distance.data[i] = s->distance, Li.data[i] = s->Li, pdf.data[i] = s->pdf;
            put_rgb(colour.data, i, s->Li_colour);
            if (wavelengths) std::copy(q.value, q.value + 4, spectral.data + 4 * i);
        });
        nb::dict d;
        d["valid"] = valid.array, d["wi"] = wi.array, d["distance"] = distance.array;
        d["Li"] = Li.array, d["pdf"] = pdf.array, d["colour"] = colour.array;
        if (wavelengths) d["spectral"] = spectral.array;
        return d;
    }

    Array<double> pdf_Li(const Points& ref, const Points& wi) const {
        const size_t n = ref.shape(0);
        check_rows(n, wi.shape(0), "wi");
        check_points(ref, "ref"), check_directions(wi, "wi");
        NewArray<double> pdf({n});
        each_row(n, [&](size_t i) {
            pdf.data[i] = source_->pdf_Li(python::point(ref, i), python::point(wi, i));
        });
        return pdf.array;
    }

    nb::dict sample_Le(const Randoms& u, const std::string& quantity, int band) const {
        const SpectralSelect select = select_of(quantity, band);
        const size_t n = u.shape(0);
        if (u.shape(1) != 7) throw nb::value_error("u must have 7 columns");
        check_uniforms(u, "u");
        NewArray<double> origin({n, 3}), direction({n, 3}), flux({n}), pdf_position({n}),
            pdf_direction({n}), colour({n, 3});
        NewArray<int32_t> cell({n});
        each_row(n, [&](size_t i) {
            const auto s = source_->sample_Le(u.data() + 7 * i, select);
            put(origin.data, i, s.origin), put(direction.data, i, s.direction);
            flux.data[i] = s.flux, pdf_position.data[i] = s.pdf_position;
            pdf_direction.data[i] = s.pdf_direction, cell.data[i] = s.cell;
            put_rgb(colour.data, i, s.flux_colour);
        });
        nb::dict d;
        d["origin"] = origin.array, d["direction"] = direction.array, d["flux"] = flux.array;
        d["pdf_position"] = pdf_position.array, d["pdf_direction"] = pdf_direction.array;
        d["cell"] = cell.array, d["colour"] = colour.array;
        return d;
    }

    nb::tuple pdf_Le(const Points& origin, const Points& direction) const {
        const size_t n = origin.shape(0);
        check_rows(n, direction.shape(0), "direction");
        check_points(origin, "origin"), check_directions(direction, "direction");
        NewArray<double> position({n}), dir({n});
        each_row(n, [&](size_t i) {
            source_->pdf_Le(python::point(origin, i), python::point(direction, i), position.data[i],
                            dir.data[i]);
        });
        return nb::make_tuple(position.array, dir.array);
    }

    Array<double> intensity(const Points& direction, const std::string& quantity, int band) const {
        const SpectralSelect select = select_of(quantity, band);
        const size_t n = direction.shape(0);
        check_directions(direction, "direction");
        NewArray<double> out({n});
        each_row(n, [&](size_t i) {
            out.data[i] = source_->intensity(python::point(direction, i), select);
        });
        return out.array;
    }

private:
    std::shared_ptr<const LightModel> model_;
    std::shared_ptr<const ComplexSource> source_;
};

}  // namespace

void bind_model(nb::module_& m) {
    const double inf = std::numeric_limits<double>::infinity();
    nb::class_<Model>(m, "Model",
                      "The paper's light-source model behind the emitter interface "
                      "(lightmodel/emitter.h). Lengths mm; radiance in the selected quantity per "
                      "(mm^2 sr).")
        .def_static("build", &Model::build, nb::arg("ray_path"), nb::arg("options"),
                    "Builds the model of a ray file; raymodel build's options as keywords, dashes "
                    "made underscores (flux_resolution=16, diagram_smoothing='none', threads=2, "
                    "...), and spectral_bin_nm, progress.")
        .def_static("load", &Model::load, nb::arg("path"), "Reads a model file (.vdb).")
        .def("save", &Model::save, nb::arg("path"), "Writes the model as one .vdb file.")
        .def("phi", &Model::phi, nb::arg("quantity") = "flux", nb::arg("band") = -1,
             "Total flux: 'flux' in the model's flux unit, or 'luminous' (lm); band >= 0 "
             "selects one spectral bin.")
        .def("phi_colour", &Model::phi_colour, "The whole flux as a linear-sRGB colour.")
        .def_prop_ro("bounds", &Model::bounds, "Box of the body, mm: (lower, upper).")
        .def("info", &Model::info, "Flux unit, totals, sizes, build options and source file.")
        .def("spheres", &Model::spheres, "The body's spheres: rows x, y, z, radius (mm).")
        .def("lattice", &Model::lattice, nb::arg("name"),
             "One lattice ('density', 'flux' or 'intensity') as arrays: dims (x, y, z), origin "
             "(lower corner of cell 0, mm), cell_size (mm), resolution, and per cell [z, y, x]: "
             "density (rays per voxel); flux (flux_unit), luminous (lm) and diagram (index, -1 "
             "for none); or diagram (the intensity cell's diagram index, -1 for none).")
        .def("diagrams", &Model::diagrams,
             "The goniometric diagrams, one row each: cell (intensity-lattice coordinates), "
             "centre (mm), flux (of the flux cells using it, flux_unit), empty.")
        .def("diagram_intensity", &Model::diagram_intensity, nb::arg("index"), nb::arg("direction"),
             "Intensity (flux_unit/sr) of the light leaving diagram `index`'s cell toward each "
             "unit direction (N x 3): its flux times the diagram's density; 0 for an empty one.")
        .def("intersect", &Model::intersect, nb::arg("origin"), nb::arg("direction"),
             nb::arg("tmax") = inf,
             "Where rays meet the body: hit, t, point, normal (arrays; rows of N x 3).")
        .def("L", &Model::L, nb::arg("origin"), nb::arg("direction"), nb::arg("tmax") = inf,
             nb::arg("quantity") = "flux", nb::arg("band") = -1,
             nb::arg("wavelengths") = nb::none(),
             "Radiance arriving at each origin along its direction from the body it meets: "
             "L, colour (linear sRGB), hit; 0 where the ray misses the body. With wavelengths "
             "(N x 4, nm) also spectral (N x 4): the radiance per nm there, scaled so that its "
             "integral against V(lambda) is the colour's luminance.")
        .def("sample_Li", &Model::sample_Li, nb::arg("ref"), nb::arg("u"),
             nb::arg("quantity") = "flux", nb::arg("band") = -1,
             nb::arg("wavelengths") = nb::none(),
             "Light sampling from points ref (N x 3) with uniform numbers u (N x 5: cell, "
             "voxel, point x 3): valid, wi, distance, Li, pdf (sr^-1), colour; with "
             "wavelengths (N x 4, nm) also spectral, as L gives it. Li / pdf (and colour / "
             "pdf) estimates the light arriving along wi over its density, without bias; pdf "
             "is what pdf_Li gives, the density MIS weighs the sample by (far from the source "
             "a stand-in for the exact one, so Li is then not the radiance itself).")
        .def("pdf_Li", &Model::pdf_Li, nb::arg("ref"), nb::arg("wi"),
             "Solid-angle density sample_Li's samples along wi from ref are weighed by: the "
             "density of drawing wi near the source, the uniform density over the cone around "
             "it far from it.")
        .def("sample_Le", &Model::sample_Le, nb::arg("u"), nb::arg("quantity") = "flux",
             nb::arg("band") = -1,
             "Photon emission from uniform numbers u (N x 7): origin, direction, flux, "
             "pdf_position (mm^-3), pdf_direction (sr^-1), cell, colour.")
        .def("pdf_Le", &Model::pdf_Le, nb::arg("origin"), nb::arg("direction"),
             "Densities of sample_Le emitting from origin along direction: (pdf_position, "
             "pdf_direction).")
        .def("intensity", &Model::intensity, nb::arg("direction"), nb::arg("quantity") = "flux",
             nb::arg("band") = -1, "Far-field intensity toward each direction, flux per sr.");
}

}  // namespace rayset::python
