// The pose network as the hybrid engine's second opinion where there is no empty room (joints
// clicked on real footage, docs/hybrid.md "Without an empty room"). The pose engine follows both
// of the person's arms; the arm compared with the tracker is the one whose shoulder lies where
// the shoulder was clicked, decided on the first frame the network sees a shoulder there.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/engines/engine.h"
#include "armmimic/engines/measurement.h"
#include "armmimic/engines/pose_options.h"

namespace armmimic::internal {

class PoseOpinion {
 public:
  // Null, with *why set, when the network cannot start (no model found) or no shoulder was
  // given in `context` (the arm could not be told).
  static std::unique_ptr<PoseOpinion> Start(const EngineContext& context,
                                            const PoseOptions& options, std::string* why);

  // The network's row for the clicked arm in `frame`; lost, with a note, until the arm is
  // told. Its `estimate` says once which arm was taken.
  ArmMeasurement Process(const Frame& frame);

 private:
  PoseOpinion(std::unique_ptr<Engine> pose, cv::Point2d shoulder, double upper_px)
      : pose_(std::move(pose)), shoulder_(shoulder), upper_px_(upper_px) {}

  std::unique_ptr<Engine> pose_;
  cv::Point2d shoulder_;       // where it was clicked
  double upper_px_;            // the clicked upper arm's length: how far a shoulder may lie off
  std::optional<bool> right_;  // the person's right arm (the network's second), once told
};

}  // namespace armmimic::internal
