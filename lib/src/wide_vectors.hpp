#pragma once

// LCMTF_WIDE_VECTORS before a function compiles it twice, for x86-64 with AVX2 and FMA and for
// the baseline, and picks one when the program loads according to the processor. For the
// arithmetic of lookups, which the baseline's two-double vectors slow down.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && \
    !defined(LCMTF_NO_WIDE_VECTORS)
#define LCMTF_WIDE_VECTORS __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define LCMTF_WIDE_VECTORS
#endif
