// The module rayset._rayset: the exception every rayset::Error becomes, and each area's
// functions (rays.cpp, photometry.cpp, model.cpp, render.cpp).
#include "arrays.h"

#include "core/error.h"

#include <fmt/format.h>
#include <sys/mman.h>

#include <cmath>
#include <new>

namespace rayset::python {

void* allocate(size_t bytes) {
    constexpr size_t kHuge = size_t(2) << 20;
    void* p = nullptr;
    if (bytes >= 2 * kHuge) {
        bytes = (bytes + kHuge - 1) / kHuge * kHuge;  // aligned_alloc wants a multiple
        p = std::aligned_alloc(kHuge, bytes);
        if (p) madvise(p, bytes, MADV_HUGEPAGE);  // a hint: without it, ordinary pages
    } else {
        p = std::malloc(bytes);
    }
    if (!p) throw std::bad_alloc();
    return p;
}

void check_rows(size_t a, size_t b, const char* what) {
    if (a != b) throw nb::value_error(fmt::format("{}: {} rows against {}", what, a, b).c_str());
}

void check_points(const Points& points, const char* what) {
    for (size_t i = 0; i < points.shape(0); ++i)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(points(i, k)))
                throw nb::value_error(
                    fmt::format("{}: row {} holds {} (finite values only)", what, i, points(i, k))
                        .c_str());
}

void check_directions(const Points& directions, const char* what) {
    check_points(directions, what);
    for (size_t i = 0; i < directions.shape(0); ++i)
        if (directions(i, 0) == 0 && directions(i, 1) == 0 && directions(i, 2) == 0)
            throw nb::value_error(
                fmt::format("{}: row {} is zero, not a direction", what, i).c_str());
}

void check_uniforms(const Randoms& u, const char* what) {
    const double* v = u.data();
    for (size_t i = 0; i < u.size(); ++i)
        if (!(v[i] >= 0 && v[i] <= 1))
            throw nb::value_error(fmt::format("{}: row {} holds {} (uniform numbers lie in [0, 1])",
                                              what, i / u.shape(1), v[i])
                                      .c_str());
}

}  // namespace rayset::python

NB_MODULE(_rayset, m) {
    namespace nb = nanobind;
    using namespace rayset::python;
    m.doc() =
        "rayset's C++ core: ray files, photometry, light-source models and the renderer. Use it "
        "through the package rayset, which wraps what this module returns.";
    // RuntimeError's subclass, so that code catching RuntimeError sees it; the message is the
    // C++ one, which names the file and the byte offset or line.
    static nb::exception<rayset::Error> error(m, "Error", PyExc_RuntimeError);
    bind_rays(m);
    bind_photometry(m);
    bind_model(m);
    bind_render(m);
    // A plugin registered with another extension (Mitsuba's emitter registry) keeps this module's
    // types alive past the interpreter's shutdown, where nanobind would report them as leaks.
    m.def("set_leak_warnings", &nb::set_leak_warnings, nb::arg("enabled"),
          "Whether nanobind reports this module's objects still alive at shutdown.");
}
