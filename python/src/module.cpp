// The module rayset._rayset: the exception every rayset::Error becomes, and each area's
// functions (rays.cpp, photometry.cpp, model.cpp, render.cpp).
#include "arrays.h"

#include "core/error.h"

#include <fmt/format.h>

namespace rayset::python {

void check_rows(size_t a, size_t b, const char* what) {
    if (a != b) throw nb::value_error(fmt::format("{}: {} rows against {}", what, a, b).c_str());
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
}
