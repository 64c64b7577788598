// The thesis path (6.2-6.3), kept selectable with LkOptions::thesis_mode: corners are detected in
// every frame, tracked into the next; those that moved more than the motion threshold are on the
// arm and propagate to later frames, and one still for more than still_frames_drop consecutive
// frames is dropped. The moving features are split by 2-means of (x, y, dx, dy); the cluster
// nearer the shoulder is the upper arm. Each part's frame-to-frame motion relative to its rotation
// centre is solved by eq. 6-16 and theta += atan2(b, a), starting from the known angles.
#include <algorithm>
#include <cmath>

#include "lk/fit.h"
#include "lk/flow.h"
#include "lk/tracker.h"

namespace armmimic::lk {
namespace {

struct Tracked {
  cv::Point2f p;
  cv::Point2f start;  // where it was first seen (decides the side)
  int still = 0;
  bool on_arm = false;  // moved once: propagates to later frames
};

class ThesisTracker : public Tracker {
 public:
  explicit ThesisTracker(const LkOptions& options) : o_(options), flow_(options) {}

  TrackerPose Start(const TrackerStart& start) override {
    flow_.Reset(start.gray);
    shoulders_ = start.shoulders;
    head_limit_y_ = start.head_limit_y;
    arm_len_ = start.arm_length_px > 0 ? start.arm_length_px : 0.4 * start.gray.rows;
    side_ = shoulders_.size() == 1 ? 0 : -1;
    if (side_ == 0) shoulder_ = shoulders_[0];
    upper_deg_ = Wrap180(o_.initial_upper_deg);
    fore_deg_ = Wrap180(o_.initial_fore_deg);
    feats_.clear();
    AddCorners(start.gray);
    return MakePose({}, {});
  }

  TrackerPose Track(const cv::Mat& gray, const cv::Mat& /*bgr*/) override {
    std::vector<cv::Point2f> pts, next;
    std::vector<unsigned char> found;
    for (const Tracked& t : feats_) pts.push_back(t.p);
    flow_.Track(gray, pts, &next, &found);
    std::vector<cv::Point2f> from, to;
    std::vector<Tracked> kept;
    for (std::size_t i = 0; i < feats_.size(); ++i) {
      if (!found[i]) continue;
      Tracked t = feats_[i];
      const cv::Point2f d = next[i] - t.p;
      const bool moving = std::hypot(d.x, d.y) > o_.motion_threshold_px;
      t.still = moving ? 0 : t.still + 1;
      if (moving) {
        t.on_arm = true;
        from.push_back(t.p);
        to.push_back(next[i]);
      }
      t.p = next[i];
      // Fresh corners that did not move are not the arm; arm features still too long go.
      if (t.on_arm && t.still <= o_.still_frames_drop) kept.push_back(t);
    }
    feats_ = kept;
    if (side_ < 0) {
      std::vector<cv::Point2f> starts, now;
      for (const Tracked& t : feats_) {
        starts.push_back(t.start);
        now.push_back(t.p);
      }
      side_ = DecideSide(shoulders_, starts, now, 2 * o_.motion_threshold_px, head_limit_y_, 3);
      if (side_ >= 0) shoulder_ = shoulders_[side_];
    }
    std::vector<cv::Point2f> upper, fore;
    if (side_ >= 0) Integrate(from, to, &upper, &fore);
    AddCorners(gray);
    return MakePose(upper, fore);
  }

 private:
  cv::Point2d Elbow() const { return shoulder_ + 0.5 * arm_len_ * DirectionVector(upper_deg_); }

  void Integrate(const std::vector<cv::Point2f>& from, const std::vector<cv::Point2f>& to,
                 std::vector<cv::Point2f>* upper, std::vector<cv::Point2f>* fore) {
    if (from.size() < 4) return;
    std::vector<cv::Point2f> motion(from.size());
    for (std::size_t i = 0; i < from.size(); ++i) motion[i] = to[i] - from[i];
    const std::vector<int> labels = TwoMeans(to, motion);
    std::vector<cv::Point2f> part[2];
    std::vector<int> index[2];
    for (std::size_t i = 0; i < labels.size(); ++i) {
      part[labels[i]].push_back(to[i]);
      index[labels[i]].push_back(static_cast<int>(i));
    }
    const cv::Point2d c0 = MeanPoint(part[0]), c1 = MeanPoint(part[1]);
    auto dist = [&](const cv::Point2d& c) {
      return std::isnan(c.x) ? 1e18 : std::hypot(c.x - shoulder_.x, c.y - shoulder_.y);
    };
    const int up = dist(c0) <= dist(c1) ? 0 : 1;
    const cv::Point2d centres[2] = {shoulder_, Elbow()};
    double* angles[2] = {&upper_deg_, &fore_deg_};
    for (int k = 0; k < 2; ++k) {
      const int cluster = k == 0 ? up : 1 - up;
      if (index[cluster].size() < 2) continue;
      std::vector<cv::Point2d> p, q;
      for (int i : index[cluster]) {
        p.emplace_back(from[i].x - centres[k].x, from[i].y - centres[k].y);
        q.emplace_back(to[i].x - centres[k].x, to[i].y - centres[k].y);
      }
      Motion2D m;
      if (FitMotion(p, q, {}, &m)) *angles[k] = Wrap180(*angles[k] + m.RotationCcwDeg());
    }
    *upper = part[up];
    *fore = part[1 - up];
  }

  void AddCorners(const cv::Mat& gray) {
    std::vector<cv::Point2f> existing;
    for (const Tracked& t : feats_) existing.push_back(t.p);
    const int room = o_.max_corners - static_cast<int>(feats_.size());
    for (const cv::Point2f& c : DetectCorners(gray, cv::Mat(), existing, room, o_)) {
      feats_.push_back({c, c, 0, false});
    }
  }

  TrackerPose MakePose(const std::vector<cv::Point2f>& upper,
                       const std::vector<cv::Point2f>& fore) const {
    if (side_ < 0) return MakeTrackerPose(upper_deg_, fore_deg_, false, {}, {}, {}, {}, {}, {});
    const cv::Point2d elbow = Elbow();
    return MakeTrackerPose(upper_deg_, fore_deg_, true, shoulder_, elbow,
                           elbow + 0.5 * arm_len_ * DirectionVector(fore_deg_), upper, fore,
                           "thesis: summed increments");
  }

  LkOptions o_;
  PyramidFlow flow_;
  std::vector<cv::Point2d> shoulders_;
  int side_ = -1;
  cv::Point2d shoulder_{kNaN, kNaN};
  double head_limit_y_ = -1;
  double arm_len_ = 0;
  double upper_deg_ = -90, fore_deg_ = -90;
  std::vector<Tracked> feats_;
};

}  // namespace

std::unique_ptr<Tracker> CreateThesisTracker(const LkOptions& options) {
  return std::make_unique<ThesisTracker>(options);
}

}  // namespace armmimic::lk
