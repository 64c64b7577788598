// Background-subtraction engine, step 1 (thesis 5.2.2-5.2.4): grey images, differencing against
// the background and the standstill, and picking connected regions. Private to src/engines.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/geometry.h"

namespace armmimic::bgsub {

// Grey level of a BGR image (or a copy of a grey one) into *gray, reusing its buffer.
void ToGray(const cv::Mat& bgr, cv::Mat* gray);

// Global brightness drift of `image` against `reference` (both CV_8UC1, same size): the median
// of image - reference over a sparse grid, skipping `exclude` (e.g. the body box). 0 when fewer
// than 16 samples remain.
int BrightnessDrift(const cv::Mat& image, const cv::Mat& reference, const cv::Rect& exclude,
                    int step = 8);

// mask = 255 where |image - reference - offset| > threshold, else 0 (CV_8UC1, same size).
void DifferenceMask(const cv::Mat& image, const cv::Mat& reference, int offset, int threshold,
                    cv::Mat* mask);

// Clears the pixels of `mask` where `bgr` looks like `background_bgr` in shadow: every channel
// darker by a similar ratio in [0.45, 0.97] (the hue kept, the brightness lowered).
void RemoveShadow(const cv::Mat& bgr, const cv::Mat& background_bgr, cv::Mat* mask);

// The colour form: 255 where any channel of |image - reference - offset| exceeds threshold
// (CV_8UC3 inputs). Sees an arm whose grey level matches what is behind it but whose hue does not.
void ColorDifferenceMask(const cv::Mat& image, const cv::Mat& reference, int offset, int threshold,
                         cv::Mat* mask);

// Keeps in *out (CV_8UC1, same size as labels, 0/255) only the pixels of component `c`.
void ComponentMask(const cv::Mat& labels, const Component& c, cv::Mat* out);

// Index of the largest component in `components`, or -1 when there is none.
int LargestComponent(const std::vector<Component>& components);

// Distance from `p` to rectangle `r` (0 inside).
double DistanceToBox(const cv::Point2d& p, const cv::Rect& r);

// Morphological closing with an elliptic kernel of `size` pixels (no-op for size <= 1), in
// place, of the part of `mask` around `box` (the region's bounding box).
void Close(cv::Mat* mask, const cv::Rect& box, int size);

}  // namespace armmimic::bgsub
