// The k-th smallest of a few hundred floats, as std::nth_element gives it, without its branches:
// the light gain takes some hundreds of such medians per frame, and on ratios of noisy pixels
// nth_element's comparisons are a coin toss the processor mispredicts half the time.
#pragma once

#include <cstddef>
#include <vector>

#include <opencv2/core.hpp>

namespace armmimic::arm {

// The value std::nth_element(first, first + k, first + n) would put at first + k (k < n; n > 0).
// Reorders [first, first + n) as it goes. With a NaN among them the result is one of the values
// or NaN, and the call returns.
float KthSmallest(float* first, std::size_t n, std::size_t k);

// The value at rank round(q (n - 1)) of `values` in ascending order (q in [0, 1]; the median at
// 0.5), by std::nth_element; NaN when there are none. For a few hundred values at most (the
// calibrations' edges and slopes, a frame's feature motions).
double NearestRankQuantile(std::vector<double> values, double q);

// x as a line in y through `points` (Theil-Sen: a point that lies on something else moves neither
// the slope nor the intercept). The slope dx/dy is the median over the pairs at least `min_dy`
// rows apart (and on different rows), NaN when there is no such pair; the intercept is the median
// of x - slope (y - y0), the line's x at row y0.
double TheilSenSlope(const std::vector<cv::Point2d>& points, double min_dy);
double MedianIntercept(const std::vector<cv::Point2d>& points, double y0, double slope);

}  // namespace armmimic::arm
