// The motion of a random arm scene: keyframe poses drawn from pose classes (ordinary reaches,
// the arm raised, the hand beside or above the head, the forearm across the torso), joined by
// minimum-jerk moves whose peak speed is drawn per move under the tier's limit, with pauses.
#include <algorithm>
#include <cmath>

#include "armmimic/core/angles.h"
#include "random_scene_model.h"

namespace armmimic::synth::random_scene {
namespace {

enum PoseClass { kHang, kOrdinary, kRaised, kByHead, kAboveHead, kAcrossTorso };

// Minimum-jerk time law: 0 -> 1 with zero velocity and acceleration at both ends. Its peak
// slope is 1.875, so a move of D degrees over T frames peaks at 1.875 D / T degrees a frame.
double MinJerk(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * t * (10.0 + t * (-15.0 + 6.0 * t));
}
constexpr double kMinJerkPeak = 1.875;

double Direction(cv::Point2d v) { return std::atan2(-v.y, v.x) * 180.0 / CV_PI; }

class Planner {
 public:
  Planner(const PersonModel& m, cv::Size size, double raised_max)
      : m_(m), size_(size), raised_max_(raised_max) {}

  bool Inside(cv::Point2d p) const {
    const double margin = 2;
    return p.x >= margin && p.y >= margin && p.x <= size_.width - 1 - margin &&
           p.y <= size_.height - 1 - margin;
  }

  // Elbow and wrist in the frame, the wrist not past the far side of the body; a keyframe also
  // keeps the hand's tip in the frame.
  bool Valid(const Pose& p, bool keyframe) const {
    if (std::fabs(p.bend_deg) > 150) return false;
    const ArmJoints j = JointsOf(m_, p, {0, 0});
    if (!Inside(j.elbow) || !Inside(j.wrist) || (keyframe && !Inside(j.tip))) return false;
    return j.wrist.x >= m_.cx - (m_.w + 4) * m_.s && j.elbow.x >= m_.cx + 0.2 * m_.w * m_.s;
  }

  bool SegmentValid(const Pose& a, const Pose& b) const {
    for (int k = 1; k <= 16; ++k) {
      const double t = k / 16.0;
      if (!Valid({a.upper_deg + (b.upper_deg - a.upper_deg) * t,
                  a.bend_deg + (b.bend_deg - a.bend_deg) * t},
                 k == 16)) {
        return false;
      }
    }
    return true;
  }

  // The pose that puts the wrist at `target`, elbow outward (away from the body). False when
  // the target is out of reach or the elbow would bend past 150 degrees.
  bool Reach(cv::Point2d target, Pose* out) const {
    const cv::Point2d s = m_.Shoulder();
    const double l1 = m_.upper * m_.s, l2 = m_.fore * m_.s;
    const cv::Point2d d = target - s;
    const double dist = cv::norm(d);
    if (dist >= l1 + l2 - 1 || dist <= std::fabs(l1 - l2) + 1) return false;
    const double alpha =
        std::acos(std::clamp((l1 * l1 + dist * dist - l2 * l2) / (2 * l1 * dist), -1.0, 1.0));
    const double base = std::atan2(d.y, d.x);
    cv::Point2d best;
    for (double sign : {-1.0, 1.0}) {
      const double a = base + sign * alpha;
      const cv::Point2d e = s + cv::Point2d(std::cos(a), std::sin(a)) * l1;
      if (sign < 0 || e.x > best.x) best = e;
    }
    out->upper_deg = Direction(best - s);
    out->bend_deg = Wrap180(Direction(target - best) - out->upper_deg);
    if (out->upper_deg < -135) out->upper_deg += 360;  // keep directions continuous
    return std::fabs(out->bend_deg) <= 150 && out->upper_deg <= 165;
  }

  bool Draw(cv::RNG& rng, PoseClass c, Pose* p) const {
    const cv::Point2d h = m_.HeadCentre();
    const double s = m_.s, rx = m_.head_rx * s, ry = m_.head_ry * s;
    switch (c) {
      case kHang:
        *p = Pose{};
        return true;
      case kOrdinary:
        *p = {rng.uniform(-90.0, 60.0), rng.uniform(0.0, 150.0)};
        return true;
      case kRaised:
        *p = {rng.uniform(60.0, raised_max_), rng.uniform(-10.0, raised_max_ > 100 ? 50.0 : 30.0)};
        return true;
      case kByHead:
        return Reach(h + cv::Point2d(rng.uniform(1.0, 1.9) * rx, rng.uniform(-0.6, 0.6) * ry), p);
      case kAboveHead:
        return Reach(h + cv::Point2d(rng.uniform(-0.6, 1.0) * rx, -ry - rng.uniform(2.0, 14.0) * s),
                     p);
      case kAcrossTorso:
        return Reach(m_.P(rng.uniform(-0.5, 0.4) * m_.w, rng.uniform(35.0, 80.0) * m_.torso_len),
                     p);
    }
    return false;
  }

 private:
  const PersonModel& m_;
  cv::Size size_;
  double raised_max_;
};

}  // namespace

Pose RandomMotion::At(double i) const {
  if (keys_.empty()) return {};
  if (i <= keys_.front().frame) return keys_.front().pose;
  for (std::size_t k = 1; k < keys_.size(); ++k) {
    if (i <= keys_[k].frame) {
      const Pose& a = keys_[k - 1].pose;
      const Pose& b = keys_[k].pose;
      const double span = keys_[k].frame - keys_[k - 1].frame;
      const double t = MinJerk(span > 0 ? (i - keys_[k - 1].frame) / span : 1.0);
      return {a.upper_deg + (b.upper_deg - a.upper_deg) * t,
              a.bend_deg + (b.bend_deg - a.bend_deg) * t};
    }
  }
  return keys_.back().pose;
}

RandomMotion PlanRandomMotion(cv::RNG& rng, const MotionPlanSpec& spec, const PersonModel& m,
                              cv::Size size, RandomSceneParams* params) {
  const Planner planner(m, size, spec.raised_max_deg);
  std::vector<PoseClass> required;
  if (spec.by_head) required.push_back(kByHead);
  if (spec.above_head) required.push_back(kAboveHead);
  if (spec.across_torso) required.push_back(kAcrossTorso);
  if (spec.raised) required.push_back(kRaised);
  for (std::size_t i = required.size(); i > 1; --i) {
    std::swap(required[i - 1], required[static_cast<std::size_t>(rng.uniform(0, int(i)))]);
  }
  std::vector<PoseClass> allowed(required.begin(), required.end());
  allowed.push_back(kOrdinary);
  allowed.push_back(kOrdinary);
  allowed.push_back(kHang);

  std::vector<MotionKey> keys{{Pose{}, 0.0, kHang}};
  bool fast_done = !spec.one_fast_move;
  int moves = 0, failures = 0;
  bool last_required = false;
  // The scene's own pose classes come first (an ordinary move now and then between them); a
  // class that cannot be reached from where the arm is gets a second chance later.
  while (keys.back().frame < spec.frames && moves < 200) {
    ++moves;
    PoseClass c = kOrdinary;
    const bool take_required = !required.empty() && (!last_required || rng.uniform(0.0, 1.0) < 0.7);
    if (take_required) {
      c = required.back();
    } else if (required.empty()) {
      c = allowed[static_cast<std::size_t>(rng.uniform(0, int(allowed.size())))];
    }
    last_required = take_required;
    const Pose& from = keys.back().pose;
    Pose to;
    bool found = false;
    for (int attempt = 0; attempt < 60 && !found; ++attempt) {
      if (!planner.Draw(rng, c, &to)) continue;
      const double du = to.upper_deg - from.upper_deg, db = to.bend_deg - from.bend_deg;
      if (std::max({std::fabs(du), std::fabs(db), std::fabs(du + db)}) < 20) continue;
      found = planner.Valid(to, true) && planner.SegmentValid(from, to);
    }
    if (take_required) {
      if (found || ++failures >= 2) {
        required.pop_back();
        failures = 0;
      } else {
        std::swap(required.front(), required.back());
      }
    }
    if (!found) continue;
    const double du = to.upper_deg - from.upper_deg, db = to.bend_deg - from.bend_deg;
    const double dist = std::max({std::fabs(du), std::fabs(db), std::fabs(du + db)});
    double speed = rng.uniform(spec.speed_min, spec.speed_max);
    if (!fast_done && (moves >= 3 || rng.uniform(0.0, 1.0) < 0.4)) {
      speed = spec.speed_max * rng.uniform(0.8, 1.0);
      fast_done = true;
    }
    const double frames = std::max(3.0, kMinJerkPeak * dist / speed);
    keys.push_back({to, keys.back().frame + frames, c});
    if (rng.uniform(0.0, 1.0) < spec.pause_chance) {
      keys.push_back({to, keys.back().frame + rng.uniform(0.2, 1.0) * spec.fps, c});
    }
  }
  for (const MotionKey& k : keys) {
    if (k.frame > spec.frames - 1) break;
    params->hand_by_head |= k.kind == kByHead;
    params->hand_above_head |= k.kind == kAboveHead;
    params->across_torso |= k.kind == kAcrossTorso;
  }
  return RandomMotion(std::move(keys));
}

}  // namespace armmimic::synth::random_scene
