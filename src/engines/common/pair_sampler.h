// The evidence map (arm_appearance.h) sampled at many points, each point's two coordinates
// added and scaled as one pair where the processor has SSE2: the same IEEE operations on each
// coordinate, so every sample is to the bit EvidenceMap::At's. Shared by the arm model's
// searches (arm_model_fit.cpp). Qt-free.
#pragma once

#include <opencv2/core.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "common/arm_appearance.h"

namespace armmimic::arm::pairs {

#if defined(__SSE2__)
using Pair = __m128d;
inline Pair PairOf(const cv::Point2d& p) { return _mm_set_pd(p.y, p.x); }
inline Pair Add(Pair a, Pair b) { return _mm_add_pd(a, b); }
inline Pair Scale(double t, Pair a) { return _mm_mul_pd(_mm_set1_pd(t), a); }
inline double X(Pair p) { return _mm_cvtsd_f64(p); }
inline double Y(Pair p) { return _mm_cvtsd_f64(_mm_unpackhi_pd(p, p)); }

// EvidenceMap::Sampler::At(X(q), Y(q)), to the bit.
class PairSampler {
 public:
  explicit PairSampler(const EvidenceMap& evidence)
      : map_(evidence),
        origin_(_mm_set_pd(map_.y0(), map_.x0())),
        limit_(_mm_set_pd(map_.rows_m1(), map_.cols_m1())) {}
  float At(Pair q) const {
    const __m128d f = _mm_sub_pd(q, origin_);
    const __m128d in = _mm_and_pd(_mm_cmpge_pd(f, _mm_setzero_pd()), _mm_cmplt_pd(f, limit_));
    if (_mm_movemask_pd(in) != 3) return 0.f;
    const __m128i i = _mm_cvttpd_epi32(f);
    const __m128 a = _mm_cvtpd_ps(_mm_sub_pd(f, _mm_cvtepi32_pd(i)));
    return map_.Blend(_mm_cvtsi128_si32(i), _mm_cvtsi128_si32(_mm_shuffle_epi32(i, 1)),
                      _mm_cvtss_f32(a), _mm_cvtss_f32(_mm_shuffle_ps(a, a, 1)));
  }

 private:
  EvidenceMap::Sampler map_;
  __m128d origin_, limit_;
};
#else
using Pair = cv::Point2d;
inline Pair PairOf(const cv::Point2d& p) { return p; }
inline Pair Add(const Pair& a, const Pair& b) { return a + b; }
inline Pair Scale(double t, const Pair& a) { return t * a; }
inline double X(const Pair& p) { return p.x; }
inline double Y(const Pair& p) { return p.y; }

class PairSampler {
 public:
  explicit PairSampler(const EvidenceMap& evidence) : map_(evidence) {}
  float At(const Pair& q) const { return map_.At(q.x, q.y); }

 private:
  EvidenceMap::Sampler map_;
};
#endif

}  // namespace armmimic::arm::pairs
