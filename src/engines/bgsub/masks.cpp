#include "bgsub/masks.h"

#include <opencv2/imgproc.hpp>

namespace armmimic::bgsub {

void ToGray(const cv::Mat& bgr, cv::Mat* gray) {
  if (bgr.channels() == 1) {
    bgr.copyTo(*gray);
  } else {
    cv::cvtColor(bgr, *gray, cv::COLOR_BGR2GRAY);
  }
}

void DifferenceMask(const cv::Mat& image, const cv::Mat& reference, int threshold, cv::Mat* mask) {
  CV_Assert(image.type() == CV_8UC1 && reference.type() == CV_8UC1 &&
            image.size() == reference.size());
  cv::absdiff(image, reference, *mask);
  cv::threshold(*mask, *mask, threshold, 255, cv::THRESH_BINARY);
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
