// Background-subtraction engine, the scene model built before the first row: the background and
// standstill images (thesis 5.2.1-5.2.2), the standing body (mask2) and its box, the shoulder
// (3/5 height, 1/6 or 5/6 width), and the arm-length reference b (5.2.3). Private to src/engines.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/angles.h"
#include "armmimic/core/geometry.h"
#include "armmimic/engines/bgsub_options.h"
#include "bgsub/arm.h"

namespace armmimic::bgsub {

// Per-frame working buffers, reused so that a frame allocates nothing after the first.
struct Buffers {
  cv::Mat person, moved, candidate, labels, arm;
  cv::Mat upper_fit;  // the person mask near the shoulder, torso removed (UpperArmFromPerson)
  std::vector<Component> components;
};

struct SceneModel {
  cv::Mat background_bgr;            // CV_8UC3, the analysed region (shadow test)
  cv::Mat background;                // CV_8UC1, the analysed region
  cv::Mat standstill_bgr;            // CV_8UC3, mean of the standstill frames (colour differencing)
  cv::Mat standstill;                // CV_8UC1, mean of the standstill frames
  std::optional<cv::Rect> body_box;  // box of mask2 (the standing body)
  int side = 0;                      // moving arm on screen right +1, left -1, unknown 0
  std::optional<cv::Point2d> fixed_shoulder;  // EngineContext::shoulder_px, region coordinates
  std::optional<cv::Point2d> arm_shoulder;    // improved: where the horizontal arm meets the body
  double head_cx = kNaN;                      // x of the top of the standstill body (the head)
  double arm_half_width_px = kNaN;            // half the thickness of the straight arm
  double ref_major_px = kNaN;                 // b: semi-major axis of the straight arm
  double ref_reach_px = kNaN;                 // its reach from the shoulder along its axis
  std::string note;                           // what went wrong while building, if anything

  // The shoulder for an arm on `side` (+1/-1): the fixed one, or the body-box rule. Empty when
  // neither is known.
  std::optional<cv::Point2d> Shoulder(int side, const BgsubOptions& options) const;
  // A length scale for "near the shoulder": the arm's reach, or half the body height.
  double ArmLengthScale() const;
  // Improved: whether the moving arm's place in the standstill is still covered (the arm did not
  // move) judged from the pixels that neither moved nor were vacated around the rest upper arm.
  bool ArmAtRest(const cv::Point2d& shoulder, const BgsubOptions& options,
                 const Buffers& buffers) const;
  // Improved: the direction of an upper arm near its rest pose, which the frame-vs-standstill
  // difference cannot see: the ray from the shoulder (within 60 degrees of the rest pose) best
  // covered by the person mask (frame vs background) once the torso, everything on the inner
  // side of the hanging arm, is removed. NaN when no such ray is covered.
  double UpperArmFromPerson(const cv::Point2d& shoulder, int arm_side, const BgsubOptions& options,
                            Buffers* buffers) const;
};

// The moving arm of `gray` (the analysed region): frame vs background gives the person, frame vs
// standstill what moved (5.2.4); their intersection's connected regions are labelled and the arm
// is picked (the largest in the thesis; the largest near the shoulder, head region excluded, when
// improved) and closed. Returns false with *note set when there is no arm. *box: the arm's box.
bool FindArmMask(const cv::Mat& gray, const cv::Mat& bgr, const SceneModel& scene,
                 const BgsubOptions& options, bool largest_only, Buffers* buffers, cv::Rect* box,
                 std::string* note);

// Builds the body box from the standstill (mask2 = |standstill - background| > threshold, the
// largest region), then measures the straight arm of `arm_length_gray` for b and the arm's side.
void BuildScene(const cv::Mat& arm_length_gray, const cv::Mat& arm_length_bgr,
                const BgsubOptions& options, Buffers* buffers, SceneModel* scene);

}  // namespace armmimic::bgsub
