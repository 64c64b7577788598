// Two per-pixel row kernels of the evidence map (arm_appearance.h), on a row's channel values as
// one flat array: sixteen values a step where the processor has SSE2, and to the bit what the
// plain loops give (the same IEEE operations, in the same order, on each value).
#pragma once

#include <cstdint>

namespace armmimic::arm {

// out[i] = cv::saturate_cast<uchar>(in[i] / gain[i]) for i < n: the frame in another light.
void DivideRow(const std::uint8_t* in, const float* gain, std::uint8_t* out, int n);

// out[i] = the square of how far in[i] lies outside [lo[i], hi[i]] (lo[i] <= hi[i]; 0 inside),
// for i < n.
void SquaredOutsideRow(const std::uint8_t* in, const float* lo, const float* hi, float* out, int n);

// The evidence from each pixel's colour probability `p[i]` (overwritten) and its change `d[i]`
// (< 0: the background is unknown there), for i < n:
//   p[i] = d[i] < 0 ? unknown_share * p[i] : p[i] * std::clamp((d[i] - low) * inv, 0.f, 1.f).
void EvidenceRow(const float* d, float* p, int n, float low, float inv, float unknown_share);

}  // namespace armmimic::arm
