// What the moving arm looks like, learnt from a frame where its joints are known, and how much
// each pixel of a later frame looks like it: the evidence a two-segment arm model is scored on
// (arm_model_fit.h). Two cues, both learnt while tracking and no background image needed:
//
// * colour: a 3-D colour histogram of the arm (sleeve, bare skin and hand) against one of its
//   surroundings, as the probability that a colour is the arm's;
// * change: a background learnt from the frames themselves, everywhere the arm is not. A pixel
//   that the background explains (a poster in the sleeve's colour, the shirt behind a forearm in
//   the same cloth) is no evidence for the arm, whatever its colour; a pixel the arm has hidden
//   since the start is judged by its colour alone.
//
// Shared by the tracking engines (lk, and the hybrid engine's two-segment model). Qt-free.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace armmimic::arm {

// The arm in one frame, in pixels of the analysed image.
struct ArmJoints {
  cv::Point2d shoulder, elbow, wrist;
};

// The arm's shape: segment lengths, the hand beyond the wrist and the half-widths, in pixels.
struct ArmShape {
  double upper_px = 0, fore_px = 0, hand_px = 0;
  double upper_hw = 3, fore_hw = 3;
};

// Paints the arm's capsules (upper arm, forearm and hand) into `mask` (CV_8U) with `value`,
// each widened by `grow_px` on every side.
void DrawArm(cv::Mat& mask, const ArmJoints& joints, const ArmShape& shape, double grow_px,
             int value = 255);

// P(arm | colour) from two colour histograms (16 levels a channel, smoothed over neighbouring
// bins): the arm's pixels against those around it, with equal priors. A colour neither has shown
// is taken as unlikely to be the arm's.
class ColourModel {
 public:
  // Learns from the pixels of `bgr` where `arm` is set against those where `around` is set
  // (both CV_8U masks of bgr's size).
  void Learn(const cv::Mat& bgr, const cv::Mat& arm, const cv::Mat& around);
  // Moves the arm's histogram towards the pixels under `arm` by `rate` (0..1).
  void Adapt(const cv::Mat& bgr, const cv::Mat& arm, double rate);
  bool valid() const { return !prob_.empty(); }
  float Probability(const cv::Vec3b& c) const { return prob_[Index(c)]; }
  // The probability table indexed by Index().
  const std::vector<float>& table() const { return prob_; }
  static int Index(const cv::Vec3b& c) { return (c[0] >> 4) << 8 | (c[1] >> 4) << 4 | c[2] >> 4; }

 private:
  static std::vector<float> Histogram(const cv::Mat& bgr, const cv::Mat& mask);
  void Rebuild();
  std::vector<float> arm_, around_, prob_;
};

class EvidenceMap;

// The scene without the moving arm, learnt from the frames: every pixel away from the arm
// follows the frames (slow light changes, a swaying body, a shadow that stays); a pixel the arm
// hid since the start is unknown until the arm uncovers it.
class LearntBackground {
 public:
  // `bgr` is the first frame; `hidden` (CV_8U) marks its pixels that show the arm.
  void Reset(const cv::Mat& bgr, const cv::Mat& hidden);
  // Follows `bgr` by `rate` (0..1) wherever `hidden` is clear, inside `region`, guarded by this
  // frame's `evidence` (computed against this background): a pixel that looks like the arm is
  // the arm where the pose did not cover it (a pose a little off, an arm faster than the pose),
  // not the scene, and learning it would hide the arm there from then on.
  // * A pixel the background explains (within the evidence's change threshold) follows by
  //   `rate` times how little it looks like the arm (at least kMinFollowShare of the rate).
  // * A changed pixel in a colour unlikely to be the arm's (a shadow, the light) follows by
  //   `rate`.
  // * A changed pixel in the arm's colour, and an unknown pixel in the arm's colour, becomes the
  //   scene only once it has held one colour for kSettleFrames updates (the arm moves on; cloth
  //   of its colour stays). An unknown pixel in another colour is taken as it is.
  void Update(const cv::Mat& bgr, const cv::Mat& hidden, double rate, const cv::Rect& region,
              const EvidenceMap& evidence, const ColourModel& colour);
  const cv::Mat& image() const { return image_; }  // CV_32FC3
  const cv::Mat& known() const { return known_; }  // CV_8U, 255 where learnt
  bool empty() const { return image_.empty(); }

 private:
  cv::Mat image_, known_;
  cv::Mat pending_;  // CV_32FC3: a changed or unknown pixel's colour while it settles
  cv::Mat settled_;  // CV_8U: updates it has kept that colour, clear of the arm
};

// Learns the arm's colour and shape from a frame where its joints are known: the colour from the
// segments' axes (and the start of the hand), the half-widths where that colour ends across each
// segment (the narrower side: the other may run into the body in the same cloth), the hand's
// length where it ends beyond the wrist, then the colour again from the whole arm against its
// surroundings out to `reach_px` from the shoulder.
struct LearntArm {
  ColourModel colour;
  ArmShape shape;
  cv::Mat mask;  // the arm's pixels in that frame (CV_8U)
};
LearntArm LearnArm(const cv::Mat& bgr, const ArmJoints& joints, double reach_px);

// Per-pixel probability that the arm is seen there, over a region of the frame (CV_32F in
// [0, 1]): the colour's probability, times how clearly the pixel differs from the learnt
// background (a difference within a pixel's neighbourhood of the background counts as none, so a
// body that sways by a pixel or two is still explained by it). The frame is first divided by the
// light it has against the background (LightGain): a shadow passing, a flicker or a drift of the
// light is neither change nor a change of the arm's colour.
class EvidenceMap {
 public:
  // `ignore` (CV_8U, frame size, may be empty) marks pixels left out of the noise estimate (the
  // arm's last known place).
  void Compute(const cv::Mat& bgr, const LearntBackground& background, const ColourModel& colour,
               const cv::Rect& region, const cv::Mat& ignore);
  // What At reads, held in a few plain values, for a loop that samples many times.
  class Sampler {
   public:
    explicit Sampler(const EvidenceMap& e)
        : data_(e.map_.empty() ? nullptr : e.map_.ptr<float>(0)),
          step_(e.map_.step1()),
          x0_(e.region_.x),
          y0_(e.region_.y),
          cols_m1_(e.cols_m1_),
          rows_m1_(e.rows_m1_) {}
    // Bilinear sample at a frame position; `outside` beyond the region.
    float At(double x, double y, float outside = 0.f) const {
      const double fx = x - x0_, fy = y - y0_;
      if (!(fx >= 0 && fy >= 0 && fx < cols_m1_ && fy < rows_m1_)) return outside;
      const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
      return Blend(ix, iy, static_cast<float>(fx - ix), static_cast<float>(fy - iy));
    }
    // The blend of the map's pixels (ix, iy) to (ix + 1, iy + 1), weighted by the position's
    // fractions `ax` and `ay` past them.
    float Blend(int ix, int iy, float ax, float ay) const {
      const float* r0 = data_ + step_ * static_cast<std::size_t>(iy) + ix;
      const float* r1 = r0 + step_;
      return (1 - ay) * ((1 - ax) * r0[0] + ax * r0[1]) + ay * ((1 - ax) * r1[0] + ax * r1[1]);
    }
    // The region's top-left corner (frame pixels) and its last columns' and rows' start: At
    // samples where x - x0() lies in [0, cols_m1()) and y - y0() in [0, rows_m1()).
    double x0() const { return x0_; }
    double y0() const { return y0_; }
    double cols_m1() const { return cols_m1_; }
    double rows_m1() const { return rows_m1_; }

   private:
    const float* data_;
    std::size_t step_;  // floats a row
    double x0_, y0_, cols_m1_, rows_m1_;
  };
  // Bilinear sample at a frame position; `outside` beyond the region.
  float At(double x, double y, float outside = 0.f) const {
    return Sampler(*this).At(x, y, outside);
  }
  const cv::Mat& map() const { return map_; }
  const cv::Rect& region() const { return region_; }
  // The change (background distance, grey levels) that counts fully, as estimated this frame.
  double change_threshold() const { return full_change_; }

 private:
  cv::Mat map_;
  cv::Rect region_;
  double cols_m1_ = 0, rows_m1_ = 0;
  double full_change_ = 0;
  cv::Mat low_, high_;  // the background's per-channel minimum and maximum over 3x3
  cv::Mat relit_;       // the region of the frame in the background's light
  std::vector<float> distances_;
  cv::Mat dist_;                // CV_32F: each pixel's distance from the background
  std::vector<float> squares_;  // one row's squared channel distances
};

}  // namespace armmimic::arm
