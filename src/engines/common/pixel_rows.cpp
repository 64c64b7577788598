#include "common/pixel_rows.h"

#include <algorithm>

#include <opencv2/core.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace armmimic::arm {
namespace {

#if defined(__SSE2__)
// Sixteen bytes as four vectors of four floats, in order.
inline void Widen(const std::uint8_t* in, __m128* f) {
  const __m128i zero = _mm_setzero_si128();
  const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in));
  const __m128i lo = _mm_unpacklo_epi8(bytes, zero), hi = _mm_unpackhi_epi8(bytes, zero);
  f[0] = _mm_cvtepi32_ps(_mm_unpacklo_epi16(lo, zero));
  f[1] = _mm_cvtepi32_ps(_mm_unpackhi_epi16(lo, zero));
  f[2] = _mm_cvtepi32_ps(_mm_unpacklo_epi16(hi, zero));
  f[3] = _mm_cvtepi32_ps(_mm_unpackhi_epi16(hi, zero));
}
#endif

}  // namespace

void DivideRow(const std::uint8_t* in, const float* gain, std::uint8_t* out, int n) {
  int i = 0;
#if defined(__SSE2__)
  // cvRound's rounding (the processor's, to nearest even), then the int clamped to 0..255 by the
  // two saturating packs, as saturate_cast does.
  for (; i + 16 <= n; i += 16) {
    __m128 f[4];
    Widen(in + i, f);
    __m128i r[4];
    for (int k = 0; k < 4; ++k) {
      r[k] = _mm_cvtps_epi32(_mm_div_ps(f[k], _mm_loadu_ps(gain + i + 4 * k)));
    }
    const __m128i packed =
        _mm_packus_epi16(_mm_packs_epi32(r[0], r[1]), _mm_packs_epi32(r[2], r[3]));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), packed);
  }
#endif
  for (; i < n; ++i) out[i] = cv::saturate_cast<uchar>(in[i] / gain[i]);
}

void SquaredOutsideRow(const std::uint8_t* in, const float* lo, const float* hi, float* out,
                       int n) {
  int i = 0;
#if defined(__SSE2__)
  // maxps differs from std::max only for NaNs and in the sign of a zero, which squaring drops.
  const __m128 zero = _mm_setzero_ps();
  for (; i + 16 <= n; i += 16) {
    __m128 f[4];
    Widen(in + i, f);
    for (int k = 0; k < 4; ++k) {
      const int j = i + 4 * k;
      const __m128 below = _mm_sub_ps(_mm_loadu_ps(lo + j), f[k]);
      const __m128 above = _mm_sub_ps(f[k], _mm_loadu_ps(hi + j));
      const __m128 e = _mm_max_ps(_mm_max_ps(below, above), zero);
      _mm_storeu_ps(out + j, _mm_mul_ps(e, e));
    }
  }
#endif
  for (; i < n; ++i) {
    const float v = in[i];
    const float e = std::max(std::max(lo[i] - v, v - hi[i]), 0.f);
    out[i] = e * e;
  }
}

void EvidenceRow(const float* d, float* p, int n, float low, float inv, float unknown_share) {
  int i = 0;
#if defined(__SSE2__)
  // std::clamp(v, 0, 1) is std::min(std::max(v, 0), 1); maxps(0, v) and minps(1, v) return v
  // exactly where std::max(v, 0) and std::min(v, 1) do (NaNs and zeros of either sign included).
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.f);
  const __m128 low4 = _mm_set1_ps(low), inv4 = _mm_set1_ps(inv);
  const __m128 share = _mm_set1_ps(unknown_share);
  for (; i + 4 <= n; i += 4) {
    const __m128 dv = _mm_loadu_ps(d + i), pv = _mm_loadu_ps(p + i);
    const __m128 v = _mm_mul_ps(_mm_sub_ps(dv, low4), inv4);
    const __m128 seen = _mm_mul_ps(pv, _mm_min_ps(one, _mm_max_ps(zero, v)));
    const __m128 unknown = _mm_cmplt_ps(dv, zero);
    _mm_storeu_ps(
        p + i, _mm_or_ps(_mm_and_ps(unknown, _mm_mul_ps(share, pv)), _mm_andnot_ps(unknown, seen)));
  }
#endif
  for (; i < n; ++i) {
    p[i] = d[i] < 0 ? unknown_share * p[i] : p[i] * std::clamp((d[i] - low) * inv, 0.f, 1.f);
  }
}

}  // namespace armmimic::arm
