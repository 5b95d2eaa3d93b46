// What the binding sources share: numpy arrays made from C++ memory, the array types the
// vectorised functions take, and the registration functions of each area.
#pragma once

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

#include "core/geometry.h"

namespace rayset::python {

namespace nb = nanobind;

// Paths: nanobind takes str and os.PathLike (pathlib) for these.
using Path = std::filesystem::path;

template <class T>
using Array = nb::ndarray<nb::numpy, T>;
// Arguments: nanobind converts other dtypes and layouts (float32, slices, lists) to these.
using Points = nb::ndarray<const double, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu>;
using Values = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using Randoms = nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;

// Memory for arrays, freed with std::free. Large blocks are aligned to 2 MB and asked to be
// backed by huge pages: filling 400 MB of fresh 4 KB pages costs 100000 page faults, more time
// than reading the rays into them.
void* allocate(size_t bytes);

// A new C-contiguous numpy array over memory it owns: filled through `data` before it reaches
// Python (also without the GIL), freed when Python drops the last reference.
template <class T>
struct NewArray {
    T* data = nullptr;
    Array<T> array;

    // zeroed = false leaves the values undefined, for arrays the caller fills whole: zeroing
    // 400 MB of rays first would cost a pass over memory of its own.
    explicit NewArray(std::initializer_list<size_t> shape, bool zeroed = true)
        : NewArray(std::vector<size_t>(shape), zeroed) {}
    explicit NewArray(const std::vector<size_t>& shape, bool zeroed = true) {
        size_t count = 1;
        for (size_t n : shape) count *= n;
        data = static_cast<T*>(allocate(std::max<size_t>(count, 1) * sizeof(T)));
        if (zeroed) std::fill(data, data + count, T());
        nb::capsule owner(data, [](void* p) noexcept { std::free(p); });
        array = Array<T>(data, shape.size(), shape.data(), owner);
    }
};

template <class T>
Array<T> to_array(const std::vector<T>& values) {
    NewArray<T> out({values.size()});
    std::copy(values.begin(), values.end(), out.data);
    return out.array;
}

// An array as a plain Python object: a property getter's result would otherwise be tied to the
// C++ object (reference_internal), which nanobind refuses for an array owning its memory.
template <class T>
nb::object object(Array<T> array) {
    return nb::cast(std::move(array), nb::rv_policy::move);
}

inline Vec3 point(const Points& points, size_t i) {
    return {points(i, 0), points(i, 1), points(i, 2)};
}
inline void put(double* out, size_t i, Vec3 v) {
    out[3 * i] = v.x, out[3 * i + 1] = v.y, out[3 * i + 2] = v.z;
}

// Rows of two arrays that go together must be as many.
void check_rows(size_t a, size_t b, const char* what);
// Values a query cannot use are refused with the first row that holds one (ValueError), before
// they reach Embree, which asserts on a ray that is not finite: points finite, directions finite
// and not zero, uniform numbers in [0, 1].
void check_points(const Points& points, const char* what);
void check_directions(const Points& directions, const char* what);
void check_uniforms(const Randoms& u, const char* what);

void bind_rays(nb::module_& m);
void bind_photometry(nb::module_& m);
void bind_model(nb::module_& m);
void bind_render(nb::module_& m);

}  // namespace rayset::python
