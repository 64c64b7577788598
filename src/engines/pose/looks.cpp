#include "pose/looks.h"

#include <algorithm>
#include <cmath>

#include "armmimic/core/angles.h"

namespace armmimic::internal {

PoseKeypoints PoseLooks::Combined() const {
  if (closer.empty()) return body;
  PoseKeypoints k = body;
  for (int i = 0; i < kPoseKeypointCount; ++i) {
    cv::Point2d sum(0, 0);
    for (const PoseKeypoints& look : closer) sum += look.px[i];
    k.px[i] = sum / static_cast<double>(closer.size());
  }
  return k;
}

double PoseLooks::DisagreementDeg(int from, int to) const {
  std::vector<double> deg = {DirectionDeg(body.px[from], body.px[to])};
  for (const PoseKeypoints& look : closer) deg.push_back(DirectionDeg(look.px[from], look.px[to]));
  double worst = 0;
  for (std::size_t a = 0; a < deg.size(); ++a) {
    for (std::size_t b = a + 1; b < deg.size(); ++b) {
      worst = std::max(worst, std::abs(AngleDiff(deg[a], deg[b])));
    }
  }
  return worst;
}

void PoseLooks::Shift(const cv::Point2d& offset) {
  for (cv::Point2d& p : body.px) p += offset;
  for (PoseKeypoints& look : closer) {
    for (cv::Point2d& p : look.px) p += offset;
  }
}

PoseLooks TakeLooks(PoseNetwork* net, const cv::Mat& image, const PoseKeypoints& body,
                    const PoseCrop& body_crop, const std::vector<PoseSide>& sides,
                    const PoseOptions& options) {
  PoseLooks looks;
  looks.body = body;
  const bool seen = std::any_of(sides.begin(), sides.end(), [&](PoseSide side) {
    return ArmOf(body, side).score >= options.min_score;
  });
  if (!seen) return looks;
  PoseCrop crop = body_crop;
  if (options.arm_crop > 0 && ArmLookCrop(body, options.arm_crop, options.crop_score, &crop)) {
    looks.closer.push_back(net->Run(image, crop));
  } else {
    crop = body_crop;
  }
  if (options.flip) {
    // Without an arm look, the mirrored look pairs with the body look itself.
    if (looks.closer.empty()) looks.closer.push_back(body);
    looks.closer.push_back(net->RunMirrored(image, crop));
  }
  return looks;
}

}  // namespace armmimic::internal
