// Hot loops compiled twice: for any x86-64 (SSE2, or plain C++ elsewhere) and for CPUs with
// AVX2, chosen at run time. A loop is written once as an always-inlined function; a wrapper
// marked RAYSET_TARGET_AVX2 instantiates it for AVX2.
//
// Both versions must make the same IEEE operations in the same order, so that a file's figures
// do not depend on the machine: the AVX2 target is "avx2" alone, without FMA, with which the
// compiler would fuse a * b + c and round once instead of twice.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__)
#define RAYSET_HAVE_AVX2_TARGET 1
#define RAYSET_TARGET_AVX2 __attribute__((target("avx2")))
#else
#define RAYSET_HAVE_AVX2_TARGET 0
#define RAYSET_TARGET_AVX2
#endif

#if defined(__GNUC__)
#define RAYSET_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define RAYSET_ALWAYS_INLINE inline
#endif

namespace rayset {

// Whether this CPU runs the AVX2 versions.
inline bool cpu_has_avx2() {
#if RAYSET_HAVE_AVX2_TARGET
    static const bool has = __builtin_cpu_supports("avx2");
    return has;
#else
    return false;
#endif
}

}  // namespace rayset
