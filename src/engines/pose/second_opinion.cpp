#include "pose/second_opinion.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "armmimic/core/angle_file.h"
#include "pose/gate.h"

namespace armmimic::internal {
namespace {

constexpr double kDegToRad = M_PI / 180;
// The widest camera the 3-D check allows for (across the frame's long side), and how many focal
// lengths it tries between that and an orthographic camera.
constexpr double kMaxFieldOfViewDeg = 90;
constexpr int kFocalSteps = 8;

// How far segment b's far end is from segment a's once both start at a's near end, over what is
// allowed for a segment of that length (at least `floor_px`): sin_max times it; > 1 disagrees.
double Misfit(const cv::Point2d& a_from, const cv::Point2d& a_to, const cv::Point2d& b_from,
              const cv::Point2d& b_to, double floor_px, double sin_max) {
  const cv::Point2d va = a_to - a_from;
  const cv::Point2d vb = b_to - b_from;
  const double length = std::max({cv::norm(va), cv::norm(vb), floor_px});
  return length > 0 ? cv::norm(vb - va) / (sin_max * length) : 0;
}

// How far the 3-D segment `world` (x right, y down, z away from the camera, metres), starting at
// image pixel `start`, turns from the image segment `image` in the image plane, over what is
// allowed. A camera projects a segment d that starts where the ray (a, 1) meets it along
// d_xy - a * d_z (a: the start's image offset from the principal point over the focal length),
// so a segment that leaves the optical axis towards or away from the camera turns in the image.
// BlazePose's world frame is the camera's turned to its axes but drawn without perspective, and
// the camera's focal length is unknown: the misfit is the least over focal lengths from a
// field of view of kMaxFieldOfViewDeg across the frame's long side to none (orthographic). It is
// the chord between the in-plane unit directions, weighted by the share of the segment that
// lies in the image plane (a segment pointing at the camera has no in-plane direction to disagree
// with), over the chord of max_deg. > 1 disagrees.
double PlaneMisfit(const cv::Vec3d& world, const cv::Point2d& start, const cv::Point2d& image,
                   const cv::Size& frame, double chord_max) {
  const double length = cv::norm(world), seen = cv::norm(image);
  if (length <= 0 || seen <= 0) return 0;
  const cv::Point2d centre(frame.width / 2.0, frame.height / 2.0);
  const double max_inverse_focal =
      2 * std::tan(kMaxFieldOfViewDeg * kDegToRad / 2) / std::max(frame.width, frame.height);
  double least = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kFocalSteps; ++i) {
    const cv::Point2d a = (start - centre) * (max_inverse_focal * i / kFocalSteps);
    const cv::Point2d in_plane(world[0] - a.x * world[2], world[1] - a.y * world[2]);
    const double plane = cv::norm(in_plane);
    if (plane <= 0) return 0;
    least = std::min(least, std::min(plane / length, 1.0) *
                                cv::norm(in_plane / plane - image / seen) / chord_max);
  }
  return least;
}

}  // namespace

std::string SecondOpinion(const PoseLooks& movenet, const PoseKeypoints& blaze,
                          const std::array<cv::Vec3d, 3>& world, const cv::Size& frame,
                          PoseSide side, const PoseOptions& options) {
  const PoseArm seen = ArmOf(movenet.body, side);
  if (seen.score < options.min_score) {
    return "MoveNet, the second opinion, does not see the arm (score " +
           FormatNumber(seen.score, 2) + ")";
  }
  const PoseKeypoints k = movenet.Combined();
  const PoseArm m = ArmOf(k, side);
  const PoseArm b = ArmOf(blaze, side);
  const double torso = TorsoPx(k, options.crop_score);
  // MoveNet's own looks must agree first (its looks' bound, the same measure): an opinion that
  // is itself unsure bears nothing out.
  const double sin_looks = std::sin(options.max_disagreement_deg * kDegToRad);
  for (const PoseKeypoints& look : movenet.closer) {
    const PoseArm c = ArmOf(look, side);
    const double unsure = std::max(
        Misfit(seen.shoulder, seen.elbow, c.shoulder, c.elbow, kUpperFloor * torso, sin_looks),
        Misfit(seen.elbow, seen.wrist, c.elbow, c.wrist, kForeFloor * torso, sin_looks));
    if (unsure > 1) {
      return "MoveNet, the second opinion, is unsure: its looks disagree (" +
             FormatNumber(unsure, 1) + " times what " +
             FormatNumber(options.max_disagreement_deg, 0) + " degrees allow)";
    }
  }
  const double max_deg = options.max_network_disagreement_deg;
  const double sin_max = std::sin(max_deg * kDegToRad);
  const double upper =
      Misfit(m.shoulder, m.elbow, b.shoulder, b.elbow, kUpperFloor * torso, sin_max);
  const double fore = Misfit(m.elbow, m.wrist, b.elbow, b.wrist, kForeFloor * torso, sin_max);
  // The shoulder against the upper arm's length: the same arm, not its twin on the other side.
  const double shoulder = cv::norm(b.shoulder - m.shoulder) /
                          (sin_max * std::max(cv::norm(m.elbow - m.shoulder), kUpperFloor * torso));
  const double chord_max = 2 * std::sin(max_deg * kDegToRad / 2);
  const double upper_3d =
      PlaneMisfit(world[1] - world[0], m.shoulder, m.elbow - m.shoulder, frame, chord_max);
  const double fore_3d =
      PlaneMisfit(world[2] - world[1], m.elbow, m.wrist - m.elbow, frame, chord_max);
  const double worst = std::max({upper, fore, shoulder, upper_3d, fore_3d});
  if (worst <= 1) return std::string();
  const char* part = worst == shoulder   ? "shoulder"
                     : worst == upper    ? "upper arm"
                     : worst == fore     ? "forearm"
                     : worst == upper_3d ? "upper arm's 3-D direction"
                                         : "forearm's 3-D direction";
  return std::string("BlazePose and MoveNet, the second opinion, disagree on the ") + part + " (" +
         FormatNumber(worst, 1) + " times what " + FormatNumber(max_deg, 0) + " degrees allow)";
}

}  // namespace armmimic::internal
