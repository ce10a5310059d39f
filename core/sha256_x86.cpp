// The SHA-256 compressor on the x86 SHA extensions (SHA-NI), picked at run time so one build
// runs on every x86-64 CPU. The state lives in the two registers the instructions want: ABEF
// and CDGH, word order reversed.
#include "core/sha256.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#include <immintrin.h>

namespace taa::sha256detail {

namespace {

#define TAA_SHA_TARGET __attribute__((target("sha,sse4.1,ssse3")))

// The next four schedule words from the sixteen before them (w[t-16..t-1] in m0..m3).
TAA_SHA_TARGET __m128i schedule(__m128i m0, __m128i m1, __m128i m2, __m128i m3) {
  const __m128i t = _mm_add_epi32(_mm_sha256msg1_epu32(m0, m1), _mm_alignr_epi8(m3, m2, 4));
  return _mm_sha256msg2_epu32(t, m3);
}

TAA_SHA_TARGET void compressShaNi(uint32_t state[8], const uint8_t* data, size_t blocks) {
  // Big-endian words: reverse the bytes of each 32-bit lane.
  const __m128i byteSwap = _mm_set_epi64x(0x0c0d0e0f08090a0bLL, 0x0405060700010203LL);
  const __m128i dcba = _mm_loadu_si128(reinterpret_cast<const __m128i*>(state));
  const __m128i hgfe = _mm_loadu_si128(reinterpret_cast<const __m128i*>(state + 4));
  const __m128i cdab = _mm_shuffle_epi32(dcba, 0xB1);
  const __m128i efgh = _mm_shuffle_epi32(hgfe, 0x1B);
  __m128i abef = _mm_alignr_epi8(cdab, efgh, 8);
  __m128i cdgh = _mm_blend_epi16(efgh, cdab, 0xF0);
  for (; blocks > 0; --blocks, data += 64) {
    const __m128i abefStart = abef, cdghStart = cdgh;
    __m128i w[4];
    for (int i = 0; i < 4; ++i) {
      w[i] = _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(data + 16 * i)),
                              byteSwap);
    }
    for (int quad = 0; quad < 16; ++quad) {
      if (quad >= 4)
        w[quad % 4] =
            schedule(w[quad % 4], w[(quad + 1) % 4], w[(quad + 2) % 4], w[(quad + 3) % 4]);
      __m128i k = _mm_add_epi32(
          w[quad % 4], _mm_loadu_si128(reinterpret_cast<const __m128i*>(kRound + 4 * quad)));
      // Two rounds take the low two words, two more the high two.
      cdgh = _mm_sha256rnds2_epu32(cdgh, abef, k);
      k = _mm_shuffle_epi32(k, 0x0E);
      abef = _mm_sha256rnds2_epu32(abef, cdgh, k);
    }
    abef = _mm_add_epi32(abef, abefStart);
    cdgh = _mm_add_epi32(cdgh, cdghStart);
  }
  const __m128i feba = _mm_shuffle_epi32(abef, 0x1B);
  const __m128i dchg = _mm_shuffle_epi32(cdgh, 0xB1);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(state), _mm_blend_epi16(feba, dchg, 0xF0));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(state + 4), _mm_alignr_epi8(dchg, feba, 8));
}

#undef TAA_SHA_TARGET

bool cpuHasShaNi() {
  unsigned eax, ebx, ecx, edx;
  if (!__get_cpuid(1, &eax, &ebx, &ecx, &edx)) return false;
  const bool ssse3 = ecx & (1u << 9), sse41 = ecx & (1u << 19);
  if (!__get_cpuid_count(7, 0, &eax, &ebx, &ecx, &edx)) return false;
  return ssse3 && sse41 && (ebx & (1u << 29));
}

}  // namespace

Compress compressAccelerated() {
  return cpuHasShaNi() ? &compressShaNi : nullptr;
}

}  // namespace taa::sha256detail

#else

namespace taa::sha256detail {
Compress compressAccelerated() {
  return nullptr;
}
}  // namespace taa::sha256detail

#endif
