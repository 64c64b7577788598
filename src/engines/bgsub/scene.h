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
  std::vector<Component> components;
};

struct SceneModel {
  cv::Mat background_bgr;            // CV_8UC3, the analysed region (the default path's model)
  cv::Mat background;                // CV_8UC1, the analysed region
  cv::Mat standstill;                // CV_8UC1, mean of the standstill frames
  std::optional<cv::Rect> body_box;  // box of mask2 (the standing body)
  int side = 0;                      // moving arm on screen right +1, left -1, unknown 0
  std::optional<cv::Point2d> fixed_shoulder;  // EngineContext::shoulder_px, region coordinates
  double ref_major_px = kNaN;                 // b: semi-major axis of the straight arm
  std::string note;                           // what went wrong while building, if anything

  // The shoulder for an arm on `side` (+1/-1): the fixed one, or the body-box rule. Empty when
  // neither is known.
  std::optional<cv::Point2d> Shoulder(int side, const BgsubOptions& options) const;
};

// The moving arm of `gray` (the analysed region): frame vs background gives the person, frame vs
// standstill what moved (5.2.4); their intersection's connected regions are labelled, the largest
// is the arm, and it is closed. Returns false with *note set when there is no arm. *box: the
// arm's box.
bool FindArmMask(const cv::Mat& gray, const SceneModel& scene, const BgsubOptions& options,
                 Buffers* buffers, cv::Rect* box, std::string* note);

// Builds the body box from the standstill (mask2 = |standstill - background| > threshold, the
// largest region), then measures the straight arm of `arm_length_gray` for b and the arm's side.
void BuildScene(const cv::Mat& arm_length_gray, const BgsubOptions& options, Buffers* buffers,
                SceneModel* scene);

}  // namespace armmimic::bgsub
