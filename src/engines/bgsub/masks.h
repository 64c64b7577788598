// Background-subtraction engine, step 1 (thesis 5.2.2-5.2.4): grey images, differencing against
// the background and the standstill, and picking connected regions. Private to src/engines.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/geometry.h"

namespace armmimic::bgsub {

// Grey level of a BGR image (or a copy of a grey one) into *gray, reusing its buffer.
void ToGray(const cv::Mat& bgr, cv::Mat* gray);

// mask = 255 where |image - reference| > threshold, else 0 (CV_8UC1, same size).
void DifferenceMask(const cv::Mat& image, const cv::Mat& reference, int threshold, cv::Mat* mask);

// Keeps in *out (CV_8UC1, same size as labels, 0/255) only the pixels of component `c`.
void ComponentMask(const cv::Mat& labels, const Component& c, cv::Mat* out);

// Index of the largest component in `components`, or -1 when there is none.
int LargestComponent(const std::vector<Component>& components);

// Morphological closing with an elliptic kernel of `size` pixels (no-op for size <= 1), in
// place, of the part of `mask` around `box` (the region's bounding box).
void Close(cv::Mat* mask, const cv::Rect& box, int size);

}  // namespace armmimic::bgsub
