// The background-subtraction engine (thesis chapter 5) behind the Engine interface: the
// standstill phase, then one measurement per frame. See docs/bgsub.md for the steps.
#include <cmath>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "arm_gate.h"
#include "armmimic/core/angles.h"
#include "bgsub_arm.h"
#include "bgsub_masks.h"
#include "bgsub_scene.h"
#include "engine_factories.h"

namespace armmimic {
namespace {

std::string SizeText(const cv::Size& s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

std::string Num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

cv::Point2d Offset(const cv::Point2d& p, const cv::Point& o) { return {p.x + o.x, p.y + o.y}; }

std::vector<cv::Point> Offset(std::vector<cv::Point> pts, const cv::Point& o) {
  for (cv::Point& p : pts) p += o;
  return pts;
}

// The upper arm within this many degrees of its rest pose is fitted in the person mask.
constexpr double kPersonFitDeg = 35;

class BgsubEngine final : public Engine {
 public:
  explicit BgsubEngine(const BgsubOptions& options) : options_(options) {}

  EngineKind kind() const override { return EngineKind::kBgsub; }

  Status Begin(const EngineContext& context) override {
    const cv::Size size = context.frame_size;
    if (size.width <= 0 || size.height <= 0) return Status::Error("bgsub: the frame size is empty");
    if (context.background.empty()) {
      return Status::Error("bgsub needs a background image (--background or --background-frames)");
    }
    if (context.background.size() != size) {
      return Status::Error("bgsub: the background image is " + SizeText(context.background.size()) +
                           " but the video is " + SizeText(size));
    }
    if (context.arm_length.empty()) return Status::Error("bgsub needs an --arm-length image");
    if (context.arm_length.size() != size) {
      return Status::Error("bgsub: the --arm-length image is " +
                           SizeText(context.arm_length.size()) + " but the video is " +
                           SizeText(size));
    }
    frame_size_ = size;
    region_ = cv::Rect(0, 0, size.width, size.height);
    if (context.roi) {
      region_ &= *context.roi;
      if (region_.area() < 16) {
        return Status::Error(
            "--roi " + std::to_string(context.roi->x) + "," + std::to_string(context.roi->y) + "," +
            std::to_string(context.roi->width) + "," + std::to_string(context.roi->height) +
            " lies outside the " + SizeText(size) + " frame");
      }
    }
    scene_ = bgsub::SceneModel();
    bgsub::ToGray(context.background(region_), &scene_.background);
    bgsub::ToGray(context.arm_length(region_), &arm_length_gray_);
    arm_length_bgr_ = context.arm_length(region_).clone();
    scene_.background_bgr = context.background(region_).clone();
    if (context.shoulder_px) {
      scene_.fixed_shoulder =
          cv::Point2d(context.shoulder_px->x - region_.x, context.shoulder_px->y - region_.y);
    }
    standstill_sum_ = cv::Mat::zeros(region_.size(), CV_32FC1);
    standstill_bgr_sum_ = cv::Mat::zeros(region_.size(), CV_32FC3);
    standstill_count_ = 0;
    was_bent_ = false;
    ArmGateOptions gate;
    gate.max_speed_deg_s = options_.max_speed_deg_s;
    gate.min_support = options_.min_support;
    gate.confirm_frames = options_.confirm_frames;
    gate.start_confirmed = false;  // until the standstill gives the rest pose (or a first run)
    gate_ = ArmGate(gate);
    begun_ = true;
    return Status::Ok();
  }

  ArmMeasurement Process(const Frame& frame) override {
    if (!begun_) throw std::logic_error("BgsubEngine::Process called before Begin");
    ArmMeasurement m;
    m.frame = frame.index;
    m.time_s = frame.time_s;
    m.file = frame.name;
    if (frame.image.size() != frame_size_) {
      m.phase = MeasurementPhase::kLost;
      m.note = "frame is " + SizeText(frame.image.size()) + ", expected " + SizeText(frame_size_);
      return m;
    }
    bgsub::ToGray(frame.image(region_), &gray_);
    // The standstill (5.2.2): the mean of the first standstill_frames frames; no rows.
    if (standstill_count_ < options_.standstill_frames) {
      cv::accumulate(gray_, standstill_sum_);
      if (!options_.thesis_mode && options_.color_difference) {
        cv::accumulate(frame.image(region_), standstill_bgr_sum_);
      }
      ++standstill_count_;
      m.phase = MeasurementPhase::kSetup;
      m.note = "standstill " + std::to_string(standstill_count_) + "/" +
               std::to_string(options_.standstill_frames);
      if (standstill_count_ == options_.standstill_frames) {
        FinishStandstill();
        // The protocol's standstill: the arm hangs at its rest pose when the rows begin.
        if (scene_.body_box || scene_.fixed_shoulder) {
          gate_.Anchor(options_.rest_deg, options_.rest_deg, frame.time_s);
        }
      }
      FillSceneOverlay(&m);
      return m;
    }
    Measure(frame, &m);
    if (!options_.thesis_mode)
      gate_.Review(&m, m.phase == MeasurementPhase::kOk ? Support(m) : kNaN);
    return m;
  }

  AngleMeta Describe() const override {
    return {{"threshold", std::to_string(options_.threshold)},
            {"standstill_frames", std::to_string(options_.standstill_frames)},
            {"straight_ratio", Num(options_.straight_ratio)},
            {"closing", std::to_string(options_.closing_size)},
            {"mode", options_.thesis_mode ? "thesis" : "improved"}};
  }

 private:
  void FinishStandstill() {
    standstill_sum_.convertTo(scene_.standstill, CV_8UC1, 1.0 / standstill_count_);
    if (!options_.thesis_mode && options_.color_difference) {
      standstill_bgr_sum_.convertTo(scene_.standstill_bgr, CV_8UC3, 1.0 / standstill_count_);
    }
    bgsub::BuildScene(arm_length_gray_, arm_length_bgr_, options_, &buffers_, &scene_);
  }

  void FillSceneOverlay(ArmMeasurement* m) const {
    const cv::Point o = region_.tl();
    if (scene_.body_box) m->body_box = *scene_.body_box + o;
    if (auto s = scene_.Shoulder(scene_.side, options_)) m->shoulder_px = Offset(*s, o);
  }

  void Measure(const Frame& frame, ArmMeasurement* m) {
    m->phase = MeasurementPhase::kLost;
    FillSceneOverlay(m);
    if (!scene_.note.empty() && !scene_.body_box && !scene_.fixed_shoulder) {
      m->note = scene_.note;
      return;
    }
    cv::Rect box;
    std::string note;
    const bool improved = !options_.thesis_mode;
    // Side unknown (no arm in the arm-length image): the largest moving region decides it.
    const bool largest_only = scene_.side == 0 && !scene_.fixed_shoulder;
    if (!bgsub::FindArmMask(gray_, frame.image(region_), scene_, options_, largest_only, &buffers_,
                            &box, &note)) {
      const std::optional<cv::Point2d> rest_shoulder = scene_.Shoulder(scene_.side, options_);
      if (improved && options_.rest_pose && rest_shoulder &&
          scene_.ArmAtRest(*rest_shoulder, options_, buffers_)) {
        FillRest(*rest_shoulder, m);
        return;
      }
      m->note = note;
      return;
    }
    int side = scene_.side;
    if (side == 0 && scene_.body_box) {
      const RegionMoments rm = ComputeMoments(buffers_.arm, box);
      side = rm.cx >= scene_.body_box->x + 0.5 * scene_.body_box->width ? 1 : -1;
    }
    const std::optional<cv::Point2d> shoulder = scene_.Shoulder(side, options_);
    if (!shoulder) {
      m->note = "no shoulder: no body in the standstill and no --shoulder";
      return;
    }
    const double upper_len = options_.upper_arm_fraction * scene_.ref_reach_px;
    const double fore_len = scene_.ref_reach_px - upper_len;
    bgsub::ArmGeometry g =
        bgsub::AnalyzeArm(buffers_.arm, box, *shoulder, options_, was_bent_, upper_len, fore_len);
    if (!g.found) {
      m->note = g.note;
      return;
    }
    if (improved && options_.rest_pose && !ForearmOnly(*shoulder, &g) &&
        std::fabs(AngleDiff(g.upper_deg, options_.rest_deg)) < kPersonFitDeg &&
        options_.upper_from_person) {
      // The upper arm near its rest pose overlaps its standstill place, where nothing moved: its
      // visible part is off its axis. The person mask shows all of it.
      const double fit = scene_.UpperArmFromPerson(*shoulder, side, options_, &buffers_);
      if (std::isfinite(fit) && std::fabs(AngleDiff(fit, options_.rest_deg)) < kPersonFitDeg) {
        bgsub::RefitWithUpper(buffers_.arm, box, *shoulder, options_, was_bent_, fit, upper_len,
                              fore_len, &g);
        g.note += ", upper arm from the person mask";
      }
    }
    was_bent_ = g.bent;
    const cv::Point o = region_.tl();
    m->phase = MeasurementPhase::kOk;
    m->note = g.note;
    m->upper_deg = Wrap180(g.upper_deg);
    m->fore_deg = Wrap180(g.fore_deg);
    m->bend_deg = g.bent ? AngleDiff(g.fore_deg, g.upper_deg) : 0.0;
    m->yaw_deg = g.bent ? kNaN : Yaw(g);
    m->upper_com_px = Offset(g.upper_com_px, o);
    m->fore_com_px = Offset(g.fore_com_px, o);
    m->shoulder_px = Offset(*shoulder, o);
    m->elbow_px = Offset(g.elbow_px, o);
    m->wrist_px = Offset(g.wrist_px, o);
    m->bent = g.bent;
    m->arm_contour = Offset(g.contour, o);
    m->arm_hull = Offset(g.hull, o);
  }

  // The upper arm at rest (no moved pixels along it) and the moving region starting near the
  // rest elbow: only the forearm moved, e.g. flexing from the hanging pose. The standstill hides
  // the upper arm, so it keeps the rest direction.
  bool ForearmOnly(const cv::Point2d& shoulder, bgsub::ArmGeometry* g) const {
    const double upper_len = options_.upper_arm_fraction * scene_.ref_reach_px;
    if (!(upper_len > 0)) return false;
    double nearest2 = 1e36;
    for (const cv::Point& p : g->contour) {
      const double dx = p.x - shoulder.x, dy = p.y - shoulder.y;
      nearest2 = std::min(nearest2, dx * dx + dy * dy);
    }
    const double nearest = std::sqrt(nearest2);
    if (nearest < 0.6 * upper_len || !scene_.ArmAtRest(shoulder, options_, buffers_)) return false;
    const double up = options_.rest_deg;
    const cv::Point2d elbow = shoulder + DirectionVector(up) * upper_len;
    const cv::Point2d com(g->whole.cx, g->whole.cy);
    g->upper_deg = up;
    g->fore_deg = ResolveDirection(g->axis_deg, elbow, com);
    g->bent = std::fabs(AngleDiff(g->fore_deg, g->upper_deg)) > 10;
    g->elbow_px = elbow;
    g->upper_com_px = shoulder + DirectionVector(up) * (upper_len / 2);
    g->fore_com_px = com;
    double far = -1;
    for (const cv::Point& p : g->contour) {
      const double d = std::hypot(p.x - elbow.x, p.y - elbow.y);
      if (d > far) far = d, g->wrist_px = p;
    }
    g->reach_px = upper_len + far;
    g->note = "upper arm at rest, forearm moved";
    return true;
  }

  // Nothing moved and the arm's standstill place is unchanged: the arm is at its rest pose.
  void FillRest(const cv::Point2d& shoulder, ArmMeasurement* m) const {
    const cv::Point o = region_.tl();
    const double upper_len = options_.upper_arm_fraction * scene_.ref_reach_px;
    const cv::Point2d dir = DirectionVector(options_.rest_deg);
    m->phase = MeasurementPhase::kOk;
    m->note = "arm at rest (standstill pose)";
    m->upper_deg = Wrap180(options_.rest_deg);
    m->fore_deg = m->upper_deg;
    m->bend_deg = 0;
    m->yaw_deg = 0;
    m->shoulder_px = Offset(shoulder, o);
    m->elbow_px = Offset(shoulder + dir * upper_len, o);
    m->wrist_px = Offset(shoulder + dir * scene_.ref_reach_px, o);
    m->upper_com_px = Offset(shoulder + dir * (upper_len / 2), o);
    m->fore_com_px = Offset(shoulder + dir * (upper_len + scene_.ref_reach_px) * 0.5, o);
  }

  // Share of the fitted arm (shoulder to elbow to wrist, the joints' ends left out) that lies on
  // the person mask (frame vs background, one pixel of tolerance): a pick that runs over the
  // empty room is not the arm. The arm's own pixels are the person's too.
  double Support(const ArmMeasurement& m) const {
    if (!m.shoulder_px || !m.elbow_px || !m.wrist_px || buffers_.person.empty()) return kNaN;
    const cv::Point2d o(region_.tl());
    const cv::Point2d joints[3] = {*m.shoulder_px - o, *m.elbow_px - o, *m.wrist_px - o};
    const cv::Mat& person = buffers_.person;
    int on = 0, total = 0;
    for (int seg = 0; seg < 2; ++seg) {
      const cv::Point2d a = joints[seg], b = joints[seg + 1];
      const double len = std::hypot(b.x - a.x, b.y - a.y);
      const int n = std::max(2, static_cast<int>(len / 2));
      for (int k = 0; k < n; ++k) {
        const double t = seg == 0 ? 0.2 + 0.8 * k / n : 0.9 * k / n;
        const cv::Point p(cvRound(a.x + t * (b.x - a.x)), cvRound(a.y + t * (b.y - a.y)));
        if (p.x < 0 || p.y < 0 || p.x >= person.cols || p.y >= person.rows) continue;
        ++total;
        bool hit = false;
        for (int dy = -1; dy <= 1 && !hit; ++dy) {
          for (int dx = -1; dx <= 1 && !hit; ++dx) {
            const cv::Point q(p.x + dx, p.y + dy);
            hit = q.x >= 0 && q.y >= 0 && q.x < person.cols && q.y < person.rows &&
                  person.at<uchar>(q) != 0;
          }
        }
        on += hit;
      }
    }
    return total > 0 ? static_cast<double>(on) / total : kNaN;
  }

  // yaw = acos(a/b) (5.2.6): a from this frame, b from the arm-length image. Improved: the arm's
  // reach from the shoulder along its axis, which a partly hidden arm does not shorten.
  double Yaw(const bgsub::ArmGeometry& g) const {
    const bool extent = !options_.thesis_mode && options_.extent_yaw;
    const double a = extent ? g.reach_px : g.axes.major;
    const double b = extent ? scene_.ref_reach_px : scene_.ref_major_px;
    if (!(b > 0) || !std::isfinite(a)) return kNaN;
    return DegFromRad(std::acos(std::min(1.0, std::max(0.0, a / b))));
  }

  BgsubOptions options_;
  bool begun_ = false;
  cv::Size frame_size_;
  cv::Rect region_;
  bgsub::SceneModel scene_;
  cv::Mat arm_length_gray_;
  cv::Mat arm_length_bgr_;
  cv::Mat standstill_sum_;
  cv::Mat standstill_bgr_sum_;
  int standstill_count_ = 0;
  bool was_bent_ = false;
  ArmGate gate_;  // honest status: a pick off the person or an impossible jump is `lost`
  cv::Mat gray_;
  bgsub::Buffers buffers_;
};

}  // namespace

namespace internal {
std::unique_ptr<Engine> CreateBgsubEngine(const BgsubOptions& options) {
  return std::make_unique<BgsubEngine>(options);
}
}  // namespace internal
}  // namespace armmimic
