// Engine: turns frames into arm measurements. One interface, a factory, the implementations
// hidden in src/engines (bgsub: thesis ch. 5, lk: ch. 6, marker: ch. 4).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/frame.h"
#include "armmimic/core/status.h"
#include "armmimic/engines/engine_options.h"
#include "armmimic/engines/measurement.h"

namespace armmimic {

// What an engine is given before the first frame. Images are CV_8UC3 BGR of the video's size.
struct EngineContext {
  cv::Size frame_size;
  double fps = 0;
  cv::Mat background;                      // bgsub, lk (optional): empty scene
  cv::Mat arm_length;                      // bgsub: straight horizontal arm at zero yaw
  cv::Mat reference;                       // marker: joint at zero yaw and zero bend
  std::optional<cv::Point2d> shoulder_px;  // fixed shoulder instead of the body-box rule
  // lk: the elbow and wrist in the start frame (given with shoulder_px): the starting directions
  // and the segment lengths, measured instead of assumed.
  std::optional<cv::Point2d> elbow_px;
  std::optional<cv::Point2d> wrist_px;
  std::optional<cv::Rect> roi;  // analyse only this rectangle
  std::string model_dir;        // pose: --model DIR (empty: the usual places)
};

class Engine {
 public:
  virtual ~Engine() = default;

  static std::unique_ptr<Engine> Create(const EngineOptions& options);

  virtual EngineKind kind() const = 0;
  // Checks the context (sizes, required images) and prepares. Errors name the image at fault.
  virtual Status Begin(const EngineContext& context) = 0;
  // Processes the next frame in order. Arm engines return kSetup for the standstill frames.
  virtual ArmMeasurement Process(const Frame& frame) = 0;
  // Parameters for the angle file's meta line ("threshold=45", ...).
  virtual AngleMeta Describe() const = 0;
};

}  // namespace armmimic
