// ArmMeasurement: what an engine reports for one frame. It carries the angle-file row values
// and the overlay data the GUI draws (segments, elbow, shoulder, centres, markers, features).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/angle_file.h"

namespace armmimic {

enum class MeasurementPhase {
  kSetup,  // a standstill/warm-up frame: consumed by the engine, no angle-file row
  kOk,     // angles estimated for this frame
  kLost,   // the engine found nothing: a `lost` row
};

struct ArmMeasurement {
  int frame = 0;
  double time_s = 0;
  MeasurementPhase phase = MeasurementPhase::kLost;
  std::string file;  // marker engine: input image name
  std::string note;  // why lost, or which rule decided (shown in the GUI)
  // A value estimated rather than measured, decided on this frame ("arm length 96 px from the
  // region of interest's height"): reported once through AnalysisCallbacks::on_estimate.
  std::string estimate;

  double upper_deg = kNaN;
  double fore_deg = kNaN;
  double yaw_deg = kNaN;
  double bend_deg = kNaN;
  double yaw_signed_deg =
      kNaN;  // marker engine: positive turns the joint's right side to the camera
  cv::Point2d upper_com_px{kNaN, kNaN};
  cv::Point2d fore_com_px{kNaN, kNaN};
  double confidence = kNaN;  // pose: 0..1, the angle file's confidence column
  // Pose engine with BlazePose: the segments' 3-D directions in the camera's frame and the
  // elbow's 3-D angle (the angle file's optional 3-D columns, angle_file.h).
  double upper_az_deg = kNaN;
  double upper_el_deg = kNaN;
  double fore_az_deg = kNaN;
  double fore_el_deg = kNaN;
  double elbow_deg = kNaN;

  // Overlay (all in full-image pixels).
  std::optional<cv::Point2d> shoulder_px;
  std::optional<cv::Point2d> elbow_px;
  std::optional<cv::Point2d> wrist_px;
  bool bent = false;
  std::vector<cv::Point> arm_contour;
  std::vector<cv::Point> arm_hull;
  std::optional<cv::Rect> body_box;
  std::vector<cv::Point2f> upper_features;  // LK
  std::vector<cv::Point2f> fore_features;   // LK
  std::vector<cv::Rect> candidate_boxes;    // marker: components that passed the threshold
  // marker: upper first, then the left and right lower ones; (nan, nan) for one not measured.
  std::vector<cv::Point2d> marker_centres;
  std::vector<cv::Point2d> cylinder_axis_px;   // marker: the lower part's axis, bottom to pivot
  std::vector<cv::Point2d> cylinder_edges_px;  // marker: silhouette, left top/bottom, right ...
  std::vector<cv::Point2d> pose_keypoints;     // pose: the 17 keypoints (pose.h order)
  std::vector<double> pose_scores;             // pose: their scores, 0..1
  // pose with BlazePose: the arm's shoulder, elbow and wrist in metres (camera axes, origin
  // between the hips), for a 3-D view.
  std::vector<cv::Vec3d> arm_world_m;

  // The pose engine with side both: the person's right arm, measured from the same inferences;
  // this measurement is then the left arm's. Null for one arm.
  std::shared_ptr<const ArmMeasurement> right_arm;
  // This measurement, and right_arm when set: one per angle file, in ArmOutputPaths' order
  // (analysis.h).
  std::vector<const ArmMeasurement*> Arms() const;
  // Arms()[arm], or this measurement when there is no such arm (one arm measured).
  const ArmMeasurement& Arm(std::size_t arm) const;

  bool row() const { return phase != MeasurementPhase::kSetup; }
  AngleRow ToRow() const;
  // A row of an angle file as a measurement: its angles and centres, no overlay shapes.
  static ArmMeasurement FromRow(const AngleRow& row);
};

}  // namespace armmimic
