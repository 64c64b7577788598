#include "bgsub/masks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include <opencv2/imgproc.hpp>

namespace armmimic::bgsub {

void ToGray(const cv::Mat& bgr, cv::Mat* gray) {
  if (bgr.channels() == 1) {
    bgr.copyTo(*gray);
  } else {
    cv::cvtColor(bgr, *gray, cv::COLOR_BGR2GRAY);
  }
}

int BrightnessDrift(const cv::Mat& image, const cv::Mat& reference, const cv::Rect& exclude,
                    int step) {
  CV_Assert(image.type() == CV_8UC1 && reference.type() == CV_8UC1 &&
            image.size() == reference.size());
  std::vector<int> diffs;
  diffs.reserve(static_cast<std::size_t>((image.rows / step + 1) * (image.cols / step + 1)));
  for (int y = step / 2; y < image.rows; y += step) {
    const uchar* a = image.ptr<uchar>(y);
    const uchar* b = reference.ptr<uchar>(y);
    const bool row_in = y >= exclude.y && y < exclude.y + exclude.height;
    for (int x = step / 2; x < image.cols; x += step) {
      if (row_in && x >= exclude.x && x < exclude.x + exclude.width) continue;
      diffs.push_back(static_cast<int>(a[x]) - static_cast<int>(b[x]));
    }
  }
  if (diffs.size() < 16) return 0;
  auto mid = diffs.begin() + static_cast<std::ptrdiff_t>(diffs.size() / 2);
  std::nth_element(diffs.begin(), mid, diffs.end());
  return *mid;
}

void DifferenceMask(const cv::Mat& image, const cv::Mat& reference, int offset, int threshold,
                    cv::Mat* mask) {
  CV_Assert(image.type() == CV_8UC1 && reference.type() == CV_8UC1 &&
            image.size() == reference.size());
  if (offset == 0) {
    cv::absdiff(image, reference, *mask);
    cv::threshold(*mask, *mask, threshold, 255, cv::THRESH_BINARY);
    return;
  }
  mask->create(image.size(), CV_8UC1);
  for (int y = 0; y < image.rows; ++y) {
    const uchar* a = image.ptr<uchar>(y);
    const uchar* b = reference.ptr<uchar>(y);
    uchar* m = mask->ptr<uchar>(y);
    for (int x = 0; x < image.cols; ++x) {
      const int d = static_cast<int>(a[x]) - static_cast<int>(b[x]) - offset;
      m[x] = (d > threshold || d < -threshold) ? 255 : 0;
    }
  }
}

void ColorDifferenceMask(const cv::Mat& image, const cv::Mat& reference, int offset, int threshold,
                         cv::Mat* mask) {
  CV_Assert(image.type() == CV_8UC3 && reference.type() == CV_8UC3 &&
            image.size() == reference.size());
  // Whole-image SIMD passes (OpenCV's) instead of a per-pixel loop over interleaved channels.
  thread_local cv::Mat shifted, diff, any;
  const cv::Mat* ref = &reference;
  if (offset != 0) {
    cv::add(reference, cv::Scalar::all(offset), shifted);
    ref = &shifted;
  }
  cv::absdiff(image, *ref, diff);
  cv::threshold(diff, diff, threshold, 255, cv::THRESH_BINARY);
  // Any channel over: every grey weight is positive, so the grey of the 0/255 image is non-zero
  // exactly where some channel is 255.
  cv::cvtColor(diff, any, cv::COLOR_BGR2GRAY);
  cv::threshold(any, *mask, 0, 255, cv::THRESH_BINARY);
}

void RemoveShadow(const cv::Mat& bgr, const cv::Mat& background_bgr, cv::Mat* mask) {
  CV_Assert(bgr.type() == CV_8UC3 && background_bgr.type() == CV_8UC3 &&
            bgr.size() == background_bgr.size() && mask->size() == bgr.size());
  // 1 / (v + 1) for every byte: a multiplication per channel instead of a division.
  static const std::array<float, 256> kInverse = [] {
    std::array<float, 256> t{};
    for (int v = 0; v < 256; ++v) t[static_cast<std::size_t>(v)] = 1.0f / (v + 1.0f);
    return t;
  }();
  for (int y = 0; y < bgr.rows; ++y) {
    uchar* m = mask->ptr<uchar>(y);
    const cv::Vec3b* f = bgr.ptr<cv::Vec3b>(y);
    const cv::Vec3b* b = background_bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      if (!m[x]) {
        // Skip empty stretches of the mask eight bytes at a time.
        while (x + 8 <= bgr.cols) {
          std::uint64_t word;
          std::memcpy(&word, m + x, sizeof word);
          if (word != 0) break;
          x += 8;
        }
        if (x >= bgr.cols || !m[x]) continue;
      }
      float lo = 10, hi = 0;
      for (int c = 0; c < 3; ++c) {
        const float r = (f[x][c] + 1.0f) * kInverse[b[x][c]];
        lo = std::min(lo, r);
        hi = std::max(hi, r);
      }
      if (lo >= 0.45f && hi <= 0.97f && hi - lo <= 0.12f) m[x] = 0;
    }
  }
}

void ComponentMask(const cv::Mat& labels, const Component& c, cv::Mat* out) {
  out->create(labels.size(), CV_8UC1);
  out->setTo(0);
  const cv::Rect box = c.box & cv::Rect(0, 0, labels.cols, labels.rows);
  for (int y = box.y; y < box.y + box.height; ++y) {
    const int* l = labels.ptr<int>(y);
    uchar* m = out->ptr<uchar>(y);
    for (int x = box.x; x < box.x + box.width; ++x) m[x] = l[x] == c.label ? 255 : 0;
  }
}

int LargestComponent(const std::vector<Component>& components) {
  int best = -1;
  for (int i = 0; i < static_cast<int>(components.size()); ++i) {
    if (best < 0 || components[static_cast<std::size_t>(i)].area_px >
                        components[static_cast<std::size_t>(best)].area_px) {
      best = i;
    }
  }
  return best;
}

double DistanceToBox(const cv::Point2d& p, const cv::Rect& r) {
  const double dx = std::max({r.x - p.x, 0.0, p.x - (r.x + r.width - 1)});
  const double dy = std::max({r.y - p.y, 0.0, p.y - (r.y + r.height - 1)});
  return std::hypot(dx, dy);
}

void Close(cv::Mat* mask, const cv::Rect& box, int size) {
  if (size <= 1) return;
  static thread_local int cached_size = 0;
  static thread_local cv::Mat kernel;
  if (cached_size != size) {
    kernel = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(size, size));
    cached_size = size;
  }
  const cv::Rect padded =
      cv::Rect(box.x - size, box.y - size, box.width + 2 * size, box.height + 2 * size) &
      cv::Rect(0, 0, mask->cols, mask->rows);
  cv::Mat region = (*mask)(padded);
  cv::morphologyEx(region, region, cv::MORPH_CLOSE, kernel);
}

}  // namespace armmimic::bgsub
