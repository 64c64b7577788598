#include "pose/second_opinion.h"

#include <algorithm>
#include <cmath>

#include "armmimic/core/angle_file.h"
#include "pose/gate.h"

namespace armmimic::internal {
namespace {

constexpr double kDegToRad = M_PI / 180;

// How far segment b's far end is from segment a's once both start at a's near end, over what is
// allowed for a segment of that length (at least `floor_px`): sin_max times it; > 1 disagrees.
double Misfit(const cv::Point2d& a_from, const cv::Point2d& a_to, const cv::Point2d& b_from,
              const cv::Point2d& b_to, double floor_px, double sin_max) {
  const cv::Point2d va = a_to - a_from;
  const cv::Point2d vb = b_to - b_from;
  const double length = std::max({cv::norm(va), cv::norm(vb), floor_px});
  return length > 0 ? cv::norm(vb - va) / (sin_max * length) : 0;
}

// How far the 3-D segment `world` (x right, y down, z away from the camera) turns from the image
// segment `image` in the image plane, over what is allowed: the chord between their in-plane
// unit directions, weighted by the share of the 3-D segment that lies in the image plane (a
// segment pointing at the camera has no in-plane direction to disagree with), over the chord of
// max_deg. > 1 disagrees.
double PlaneMisfit(const cv::Vec3d& world, const cv::Point2d& image, double chord_max) {
  const cv::Point2d in_plane(world[0], world[1]);
  const double length = cv::norm(world), plane = cv::norm(in_plane), seen = cv::norm(image);
  if (length <= 0 || plane <= 0 || seen <= 0) return 0;
  return (plane / length) * cv::norm(in_plane / plane - image / seen) / chord_max;
}

}  // namespace

std::string SecondOpinion(const PoseLooks& movenet, const PoseKeypoints& blaze,
                          const std::array<cv::Vec3d, 3>& world, PoseSide side,
                          const PoseOptions& options) {
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
  const double upper_3d = PlaneMisfit(world[1] - world[0], m.elbow - m.shoulder, chord_max);
  const double fore_3d = PlaneMisfit(world[2] - world[1], m.wrist - m.elbow, chord_max);
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
