#include "lk/body_box.h"

#include <vector>

#include <opencv2/imgproc.hpp>

#include "common/colour_difference.h"

namespace armmimic::lk {
namespace {
// Pieces of the person at least this fraction of the largest one widen the body box.
constexpr double kPieceOfLargest = 0.1;
}  // namespace

BodyBox FindBodyBox(const cv::Mat& background, const cv::Mat& standstill,
                    const LkOptions& options) {
  BodyBox out;
  if (background.empty() || standstill.empty() || background.size() != standstill.size()) {
    return out;
  }
  cv::Mat mask = ColourDifferenceMask(background, standstill, options.body_threshold);
  // Close small gaps (a shirt close to the wall colour) before taking the largest region.
  cv::morphologyEx(mask, mask, cv::MORPH_CLOSE,
                   cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  int best = -1, best_area = 0;
  for (int i = 1; i < n; ++i) {
    const int area = stats.at<int>(i, cv::CC_STAT_AREA);
    if (area > best_area) {
      best_area = area;
      best = i;
    }
  }
  // A body smaller than 0.5 % of the picture is noise, not a person.
  if (best < 0 || best_area < 0.005 * mask.total()) return out;
  out.found = true;
  const auto box_of = [&](int i) {
    return cv::Rect(stats.at<int>(i, cv::CC_STAT_LEFT), stats.at<int>(i, cv::CC_STAT_TOP),
                    stats.at<int>(i, cv::CC_STAT_WIDTH), stats.at<int>(i, cv::CC_STAT_HEIGHT));
  };
  out.box = box_of(best);
  if (!options.thesis_mode) {
    // A shirt close to the wall's colour splits the person into pieces (head, hands, trousers);
    // every large piece belongs to the box.
    for (int i = 1; i < n; ++i) {
      if (i != best && stats.at<int>(i, cv::CC_STAT_AREA) >= kPieceOfLargest * best_area) {
        out.box |= box_of(i);
      }
    }
  }
  const double height =
      options.thesis_mode ? options.shoulder_height : options.anchored_shoulder_height;
  const double inset =
      options.thesis_mode ? options.shoulder_inset : options.anchored_shoulder_inset;
  const double y = out.box.y + out.box.height * (1.0 - height);
  out.left_shoulder = {out.box.x + out.box.width * inset, y};
  out.right_shoulder = {out.box.x + out.box.width * (1.0 - inset), y};
  return out;
}

}  // namespace armmimic::lk
