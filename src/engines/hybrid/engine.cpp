// The hybrid engine (docs/hybrid.md): lk's model tracker carries the arm, started from the
// standstill's self-calibration (or clicked joints, or the pose network), and bgsub's
// background difference measures the same arm afresh in every frame as a second opinion. A
// row is `ok` only when both are and they place each segment alike (hybrid/agreement.h); its
// directions are lk's, its yaw bgsub's (a straight arm's foreshortening against the calibrated
// length). Without a background and an arm-length image (joints clicked on footage with no
// empty room) there is no second opinion, and the rows are lk's alone, as the header and the
// first row's estimate say.
#include <algorithm>
#include <cmath>
#include <string>

#include "armmimic/core/angle_file.h"
#include "common/engine_internal.h"
#include "hybrid/agreement.h"

namespace armmimic {
namespace {

// The two measurements' confidences as one: the lower (either may be unrated, nan).
double Lower(double a, double b) {
  if (!std::isfinite(a)) return b;
  if (!std::isfinite(b)) return a;
  return std::min(a, b);
}

void Lose(ArmMeasurement* m, const std::string& why) {
  m->phase = MeasurementPhase::kLost;
  m->upper_deg = m->fore_deg = m->yaw_deg = m->bend_deg = kNaN;
  m->upper_com_px = m->fore_com_px = cv::Point2d(kNaN, kNaN);
  m->note = why;
}

class HybridEngine final : public Engine {
 public:
  HybridEngine(const HybridOptions& hybrid, const LkOptions& lk, const BgsubOptions& bgsub)
      : o_(hybrid), lk_options_(lk), bgsub_options_(bgsub) {
    // One standstill for both: the frames lk averages are the frames bgsub does.
    bgsub_options_.standstill_frames = lk_options_.standstill_frames;
  }

  EngineKind kind() const override { return EngineKind::kHybrid; }

  Status Begin(const EngineContext& context) override {
    lk_ = internal::CreateLkEngine(lk_options_);
    bgsub_.reset();
    if (Status st = lk_->Begin(context); !st) return st;
    if (!context.background.empty() && !context.arm_length.empty()) {
      bgsub_ = internal::CreateBgsubEngine(bgsub_options_);
      if (Status st = bgsub_->Begin(context); !st) return st;
    }
    first_row_ = true;
    return Status::Ok();
  }

  ArmMeasurement Process(const Frame& frame) override {
    if (!lk_) throw std::logic_error("hybrid: Process() before a successful Begin()");
    ArmMeasurement m = lk_->Process(frame);
    if (!bgsub_) {
      if (m.row() && first_row_) {
        first_row_ = false;
        m.estimate = Join(m.estimate,
                          "hybrid: no background and arm-length image, so no second opinion: "
                          "the rows are the tracker's alone");
      }
      return m;
    }
    const ArmMeasurement b = bgsub_->Process(frame);
    m.estimate = Join(m.estimate, b.estimate);
    if (!m.row()) return m;  // the standstill: both average it
    first_row_ = false;
    // The background difference's own shapes, drawn under the tracker's joints.
    m.arm_contour = b.arm_contour;
    m.arm_hull = b.arm_hull;
    if (!m.body_box) m.body_box = b.body_box;
    if (m.phase != MeasurementPhase::kOk) {
      m.note = "the tracker: " + m.note;
      return m;
    }
    if (b.phase == MeasurementPhase::kSetup) {
      Lose(&m, "the background difference, the second opinion, is still taking the standstill");
      return m;
    }
    if (b.phase != MeasurementPhase::kOk) {
      Lose(&m, "the background difference, the second opinion: " + b.note);
      return m;
    }
    if (const std::string why = internal::Disagreement(m, b, o_); !why.empty()) {
      Lose(&m, why);
      return m;
    }
    m.yaw_deg = b.yaw_deg;
    m.confidence = Lower(m.confidence, b.confidence);
    return m;
  }

  AngleMeta Describe() const override {
    AngleMeta meta = {{"second_opinion", bgsub_ ? "bgsub" : "none"},
                      {"max_disagreement", FormatNumber(o_.max_disagreement_deg, 2)},
                      {"joint_px", FormatNumber(o_.joint_px, 2)}};
    if (lk_) {
      for (auto& [key, value] : lk_->Describe()) meta.emplace_back("lk_" + key, value);
    }
    if (bgsub_) {
      for (auto& [key, value] : bgsub_->Describe()) meta.emplace_back("bgsub_" + key, value);
    }
    return meta;
  }

 private:
  static std::string Join(const std::string& a, const std::string& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return a + "; " + b;
  }

  HybridOptions o_;
  LkOptions lk_options_;
  BgsubOptions bgsub_options_;
  std::unique_ptr<Engine> lk_;
  std::unique_ptr<Engine> bgsub_;  // the second opinion; null without a background
  bool first_row_ = true;
};

}  // namespace

namespace internal {

std::unique_ptr<Engine> CreateHybridEngine(const HybridOptions& hybrid, const LkOptions& lk,
                                           const BgsubOptions& bgsub) {
  return std::make_unique<HybridEngine>(hybrid, lk, bgsub);
}

}  // namespace internal
}  // namespace armmimic
