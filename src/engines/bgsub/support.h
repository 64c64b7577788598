// Background-subtraction engine, default path: the support rule (common/arm_support.h) on the
// engine's own pixels. A fitted pose stays `ok` only where its segments lie on pixels that show an
// arm now, and not in a region wider than the arm (the flanks are judged on the new evidence
// only). An arm now is the person where the standstill was not, or the standstill's own arm still
// in place, unchanged; but an unchanged pixel of the standstill's arm counts only where the
// arm-length image (the arm raised) showed something else there: where what the hanging arm
// covers looks like the arm (a sleeve in the shirt's colour), an unchanged pixel cannot tell the
// arm from its absence, and a pose found there would be the standstill's pose repeated, not
// measured. And a changed pixel of the standstill's arm that now looks like the arm-length image
// there is what the arm uncovered when it left (the shirt behind it), not new arm. The reference is
// the standstill's own arm, hanging along the rest direction, on the standstill's person. Private
// to src/engines.
#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "bgsub/calib.h"
#include "common/arm_support.h"

namespace armmimic::bgsub {

class FitSupport {
 public:
  // `rect` is the evidence window inside the region (the masks' area). `standstill_person` and
  // `uncovered` (CV_8U, the region's size): the standstill's pixels that differ from the empty
  // room, and the arm-length image's pixels that differ from the standstill.
  void Begin(const ArmCalibration& cal, double upper_px, double rest_deg, const cv::Rect& rect,
             const cv::Mat& standstill_person, const cv::Mat& uncovered);
  // The pose with these directions from the calibrated shoulder (region coordinates); `scale`
  // foreshortens both segments alike, and the upper arm is at `split` of its calibrated length,
  // the forearm the rest of the reach (bgsub/fit.h).
  arm::ArmJoints Joints(double upper_deg, double fore_deg, double scale = 1,
                        double split = 1) const;
  // Empty when `pose` is supported by this frame's `person` and `moved` masks and the pixels that
  // differ from the arm-length image (`not_uncovered`; all CV_8U of the window); otherwise why it
  // is `lost`.
  std::string Check(const arm::ArmJoints& pose, const cv::Mat& person, const cv::Mat& moved,
                    const cv::Mat& not_uncovered);

 private:
  cv::Point2d shoulder_;
  cv::Point tl_;
  arm::ArmShape shape_;
  arm::SupportRule rule_;
  cv::Mat rest_mask_;    // the standstill's arm where it differs from what it covers
  cv::Mat rest_region_;  // the standstill's arm
  cv::Mat new_arm_, shows_arm_, revealed_;  // per frame
};

}  // namespace armmimic::bgsub
