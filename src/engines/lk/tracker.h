// The two arm trackers of the LK engine behind one small interface: the thesis path (summed
// increments of 2-means clusters, thesis 6.3) and the anchored path (absolute re-fit of every
// part against reference positions, the improvement over thesis 6.4). Coordinates are those of
// the analysed image (the ROI); the engine adds the ROI offset.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/angles.h"
#include "armmimic/engines/lk_options.h"

namespace armmimic::lk {

struct TrackerStart {
  cv::Mat gray;  // the frame with the known starting posture (CV_8U)
  cv::Mat bgr;   // the same frame in colour (CV_8UC3)
  // One shoulder when known; two (left, right) when the side is decided by the first motion.
  std::vector<cv::Point2d> shoulders;
  bool shoulder_fixed = false;  // given by the user: not refined from the motion
  double arm_length_px = 0;     // prior: shoulder to wrist
  // Measured segment lengths (clicked joints); 0 when unknown. When both are given they are used
  // as they are: not re-learnt from the sleeve or the features.
  double upper_length_px = 0;
  double fore_length_px = 0;
  double head_limit_y = -1;  // motion above this line (the head) does not decide the side
};

struct TrackerPose {
  bool ok = false;
  std::string note;
  double upper_deg = kNaN;
  double fore_deg = kNaN;
  bool have_shoulder = false;  // false while the side is still undecided
  // How much of this frame's evidence backs the pose, 0..1 (nan: not rated): the weaker part's
  // share of sleeve and feature support (RateSupport in anchored_features.cpp).
  double support = kNaN;
  // The pose is tracked on as confident, but its row is withheld: the tracker's own evidence
  // cannot tell it from a rival (another forearm direction explaining the forearm about as well,
  // or a pose on pixels never seen without the arm while the arm was seen elsewhere). `support`
  // is then 0 and the row lost; a second measurement taken apart from this tracker may decide it
  // (the hybrid engine). `rival_apart_deg`: how far the rival is, at least; `fit_support`: the
  // support the fit alone gives.
  bool undecided = false;
  double rival_apart_deg = kNaN;
  double fit_support = kNaN;
  cv::Point2d shoulder{kNaN, kNaN}, elbow{kNaN, kNaN}, wrist{kNaN, kNaN};
  cv::Point2d upper_com{kNaN, kNaN}, fore_com{kNaN, kNaN};
  std::vector<cv::Point2f> upper_features, fore_features;
};

class Tracker {
 public:
  virtual ~Tracker() = default;
  virtual TrackerPose Start(const TrackerStart& start) = 0;
  virtual TrackerPose Track(const cv::Mat& gray, const cv::Mat& bgr) = 0;
  // The time stamp of the frame given to the next Start() or Track(), seconds.
  void SetTime(double time_s) { time_s_ = time_s; }

 protected:
  double time_s_ = 0;
};

std::unique_ptr<Tracker> CreateThesisTracker(const LkOptions& options);
std::unique_ptr<Tracker> CreateAnchoredTracker(const LkOptions& options);
// The two-segment model tracker (lk/model_tracker.cpp): needs the joints in the start frame.
std::unique_ptr<Tracker> CreateModelTracker(const LkOptions& options);

// Of `shoulders`, the one whose side moved first: the index whose half of the picture (split
// halfway between the shoulders) holds at least `min_count` features that moved more than
// `min_motion_px` from where they started, below `head_limit_y`; -1 while undecided.
int DecideSide(const std::vector<cv::Point2d>& shoulders, const std::vector<cv::Point2f>& start,
               const std::vector<cv::Point2f>& now, double min_motion_px, double head_limit_y,
               int min_count);

// Mean of `points`, or nan when empty.
cv::Point2d MeanPoint(const std::vector<cv::Point2f>& points);

// A tracker's pose. While the side is undecided only the angles are set (the starting posture)
// with a note saying so; otherwise the joints, the features of each part and their centres of
// mass (the segment's midpoint for a part with no features) are filled in.
TrackerPose MakeTrackerPose(double upper_deg, double fore_deg, bool side_decided,
                            const cv::Point2d& shoulder, const cv::Point2d& elbow,
                            const cv::Point2d& wrist, std::vector<cv::Point2f> upper_features,
                            std::vector<cv::Point2f> fore_features, std::string note);

}  // namespace armmimic::lk
