// Columns to ray records: what RayReader::read() hands out, on the caller's thread, for every
// chunk of every file, so it is written with the transposes a compiler does not find itself.
#include "converters/rays/ray.h"

#include <cstddef>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rayset {

// Four rays at a time as ten floats each: (origin, direction x) and (direction y, z, radiant,
// luminous) are two 4 x 4 transposes, (wavelength, spectrum) pairs one interleave.
static_assert(sizeof(Ray) == 10 * sizeof(float) && offsetof(Ray, direction) == 12 &&
                  offsetof(Ray, radiant) == 24 && offsetof(Ray, wavelength) == 32 &&
                  offsetof(Ray, spectrum) == 36,
              "to_rays writes Ray as ten packed 4-byte fields");

void RayColumns::to_rays(RayChunk& chunk) const {
    const size_t n = size();
    chunk.rays.resize(n);
    size_t i = 0;
#if defined(__SSE2__)
    // Stores through float pointers into Ray: _mm_storeu_ps and _mm_store*_pi may alias anything.
    float* out = reinterpret_cast<float*>(chunk.rays.data());
    for (; i + 4 <= n; i += 4, out += 40) {
        __m128 a0 = _mm_loadu_ps(&ox[i]), a1 = _mm_loadu_ps(&oy[i]), a2 = _mm_loadu_ps(&oz[i]),
               a3 = _mm_loadu_ps(&dx[i]);
        _MM_TRANSPOSE4_PS(a0, a1, a2, a3);
        __m128 b0 = _mm_loadu_ps(&dy[i]), b1 = _mm_loadu_ps(&dz[i]), b2 = _mm_loadu_ps(&radiant[i]),
               b3 = _mm_loadu_ps(&luminous[i]);
        _MM_TRANSPOSE4_PS(b0, b1, b2, b3);
        const __m128 w = _mm_loadu_ps(&wavelength[i]);
        const __m128 s =
            _mm_castsi128_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(&spectrum[i])));
        const __m128 low = _mm_unpacklo_ps(w, s),
                     high = _mm_unpackhi_ps(w, s);  // (w0 s0 w1 s1), (w2 s2 w3 s3)
        _mm_storeu_ps(out, a0), _mm_storeu_ps(out + 4, b0),
            _mm_storel_pi(reinterpret_cast<__m64*>(out + 8), low);
        _mm_storeu_ps(out + 10, a1), _mm_storeu_ps(out + 14, b1),
            _mm_storeh_pi(reinterpret_cast<__m64*>(out + 18), low);
        _mm_storeu_ps(out + 20, a2), _mm_storeu_ps(out + 24, b2),
            _mm_storel_pi(reinterpret_cast<__m64*>(out + 28), high);
        _mm_storeu_ps(out + 30, a3), _mm_storeu_ps(out + 34, b3),
            _mm_storeh_pi(reinterpret_cast<__m64*>(out + 38), high);
    }
#endif
    for (; i < n; ++i) chunk.rays[i] = ray(i);
    chunk.extra = extra;
    chunk.first_index = first_index;
}

}  // namespace rayset
