// AnalysisOptions::Check(): the rules the analysis options must satisfy before anything is
// read, each error keyed by its setting ("analysis.start"), so each shell names its own flag or
// field.
// Length: Check is one flat list of rules in the order their errors are reported: the
// calibration inputs first, then each engine's own.
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/engines/analysis.h"

namespace armmimic {
namespace {

// Shorter clicked segments give no usable direction or length.
constexpr double kMinClickedSegmentPx = 4;

}  // namespace

Status AnalysisOptions::Check() const {
  if (auto_calibrate) {
    if (engine.kind == EngineKind::kBgsub || engine.kind == EngineKind::kMarker ||
        engine.kind == EngineKind::kPose) {
      return Status::Error("analysis.auto_calibrate",
                           std::string("auto-calibration is for the tracking engines, not the ") +
                               EngineName(engine.kind) + " engine");
    }
    if (shoulder_px || elbow_px || wrist_px) {
      return Status::Error("analysis.auto_calibrate",
                           "auto-calibration finds the joints itself: give it or the shoulder, "
                           "elbow and wrist, not both");
    }
  }
  if (calibrate_side == PoseSide::kBoth && (auto_calibrate || engine.kind != EngineKind::kPose)) {
    return Status::Error("analysis.calibrate_side",
                         "auto-calibration starts one arm: left, right or the better seen, not "
                         "both (both arms in one pass is the pose engine's)");
  }
  const bool tracking = engine.kind == EngineKind::kLk || engine.kind == EngineKind::kHybrid;
  if (!tracking && (elbow_px || wrist_px)) {
    return Status::Error(elbow_px ? "analysis.elbow" : "analysis.wrist",
                         std::string(elbow_px ? "the elbow" : "the wrist") +
                             " is used by the lk and hybrid engines only");
  }
  if (inputs.empty()) return Status::Error("no INPUT given (a video, images or a folder)");
  if (start < 0) {
    return Status::Error("analysis.start",
                         "the start frame must be 0 or more (got " + std::to_string(start) + ")");
  }
  if (background_frames < 0) {
    return Status::Error("analysis.background_frames",
                         "the number of background frames must be at least 1 (got " +
                             std::to_string(background_frames) + ")");
  }
  if (roi && (roi->x < 0 || roi->y < 0 || roi->width <= 0 || roi->height <= 0)) {
    return Status::Error("analysis.roi", "the region of interest needs X,Y >= 0 and W,H > 0");
  }
  const bool has_bg = !background_path.empty();
  const bool has_frames = background_frames > 0;
  switch (engine.kind) {
    case EngineKind::kBgsub:
      if (arm_length_path.empty()) {
        return Status::Error("analysis.arm_length",
                             "the bgsub engine needs an arm-length image (thesis 5.2.3)");
      }
      if (has_bg == has_frames) {
        return Status::Error("analysis.background_frames",
                             "the bgsub engine needs exactly one of a background image and a "
                             "number of background frames");
      }
      break;
    case EngineKind::kLk:
    case EngineKind::kHybrid:
      if ((elbow_px || wrist_px) && !(shoulder_px && elbow_px && wrist_px)) {
        return Status::Error(
            shoulder_px ? (elbow_px ? "analysis.wrist" : "analysis.elbow") : "analysis.shoulder",
            "the elbow and wrist go together with the shoulder: the arm's three "
            "joints in the start frame");
      }
      if (elbow_px && wrist_px && shoulder_px) {
        const double upper = cv::norm(*elbow_px - *shoulder_px);
        const double fore = cv::norm(*wrist_px - *elbow_px);
        if (upper < kMinClickedSegmentPx || fore < kMinClickedSegmentPx) {
          return Status::Error(
              upper < kMinClickedSegmentPx ? "analysis.elbow" : "analysis.wrist",
              std::string(upper < kMinClickedSegmentPx ? "the elbow" : "the wrist") +
                  " is less than " + std::to_string(int(kMinClickedSegmentPx)) +
                  " pixels from the " + (upper < kMinClickedSegmentPx ? "shoulder" : "elbow") +
                  ": the segment has no direction");
        }
      }
      if (!has_bg && !has_frames && !shoulder_px && !auto_calibrate) {
        return Status::Error("analysis.shoulder",
                             std::string("the ") + EngineName(engine.kind) +
                                 " engine needs a background image, background frames, a fixed "
                                 "shoulder or auto-calibration");
      }
      if (has_bg && has_frames) {
        return Status::Error("analysis.background",
                             "a background image and background frames cannot both be given");
      }
      break;
    case EngineKind::kMarker:
      if (reference_path.empty()) {
        return Status::Error("analysis.reference", "the marker engine needs a reference image");
      }

      break;
    case EngineKind::kPose:
      break;  // needs nothing but the model
  }
  return engine.Check();
}

}  // namespace armmimic
