#pragma once
// Treats subnormal floats as zero for the scope of a tick. A dent that decays ring by ring reaches
// values below 1e-38 a few hundred rings out; arithmetic on those subnormals is 10-100x slower
// on x86, which made a whole-model tick at 100k vertices grow from 17 to 95 ms as the dent
// spread. Flush-to-zero and denormals-are-zero (MXCSR) are set on entry and restored on exit, so
// nothing outside the tick is affected. Elsewhere than x86 with SSE it does nothing.

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

namespace palpate {

class FlushDenormals {
public:
#if defined(__SSE__) || defined(__x86_64__)
    FlushDenormals() : mSaved(_mm_getcsr()) { _mm_setcsr(mSaved | kFlushToZero | kDenormalsAreZero); }
    ~FlushDenormals() { _mm_setcsr(mSaved); }
#else
    FlushDenormals() = default;
#endif
    FlushDenormals(const FlushDenormals&) = delete;
    FlushDenormals& operator=(const FlushDenormals&) = delete;

private:
#if defined(__SSE__) || defined(__x86_64__)
    static constexpr unsigned kFlushToZero = 0x8000u;
    static constexpr unsigned kDenormalsAreZero = 0x0040u;
    unsigned mSaved;
#endif
};

}  // namespace palpate
