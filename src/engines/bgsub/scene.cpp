// The bgsub scene: the shoulder and arm length from the calibration images, and the arm's mask
// in each frame (two-step differencing, components, the arm's pick).
// Length: FindArmMask is the thesis' differencing pipeline, its stages sharing the search box and
// buffers.
#include "bgsub/scene.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "bgsub/masks.h"

namespace armmimic::bgsub {

std::optional<cv::Point2d> SceneModel::Shoulder(int arm_side, const BgsubOptions& options) const {
  if (fixed_shoulder) return fixed_shoulder;
  if (!body_box || arm_side == 0) return std::nullopt;
  const cv::Rect& b = *body_box;
  const double fx = arm_side > 0 ? 1.0 - options.shoulder_side : options.shoulder_side;
  return cv::Point2d(b.x + fx * b.width, b.y + (1.0 - options.shoulder_height) * b.height);
}

bool FindArmMask(const cv::Mat& gray, const SceneModel& scene, const BgsubOptions& options,
                 Buffers* buf, cv::Rect* box, std::string* note) {
  // Two-step differencing (5.2.4).
  DifferenceMask(gray, scene.background, options.threshold, &buf->person);
  DifferenceMask(gray, scene.standstill, options.threshold, &buf->moved);
  cv::bitwise_and(buf->person, buf->moved, buf->candidate);

  // Flood-fill connected regions (core MaskComponents), the largest kept.
  buf->components = MaskComponents(buf->candidate, &buf->labels);
  const int pick = LargestComponent(buf->components);
  if (pick < 0) {
    *note = "nothing moved";
    return false;
  }
  const Component& c = buf->components[static_cast<std::size_t>(pick)];
  if (c.area_px < options.min_arm_area_px) {
    *note = "moving region smaller than " + std::to_string(options.min_arm_area_px) + " px";
    return false;
  }
  ComponentMask(buf->labels, c, &buf->arm);
  // Morphological closing fills the small gaps the threshold leaves.
  const int pad = options.closing_size;
  *box = cv::Rect(c.box.x - pad, c.box.y - pad, c.box.width + 2 * pad, c.box.height + 2 * pad) &
         cv::Rect(0, 0, gray.cols, gray.rows);
  Close(&buf->arm, c.box, options.closing_size);
  return true;
}

void BuildScene(const cv::Mat& arm_length_gray, const BgsubOptions& options, Buffers* buf,
                SceneModel* scene) {
  // mask2: the standing body, the largest region of |standstill - background| > threshold.
  DifferenceMask(scene->standstill, scene->background, options.threshold, &buf->person);
  std::vector<Component> body = MaskComponents(buf->person, nullptr);
  const int largest = LargestComponent(body);
  if (largest >= 0 && body[static_cast<std::size_t>(largest)].area_px >= options.min_arm_area_px) {
    scene->body_box = body[static_cast<std::size_t>(largest)].box;
  } else if (!scene->fixed_shoulder) {
    scene->note = "no body in the standstill frames (check the background and the threshold)";
  }

  // The arm-length image: the straight horizontal arm at zero yaw gives b (5.2.3).
  if (arm_length_gray.empty()) return;
  cv::Rect box;
  std::string note;
  if (!FindArmMask(arm_length_gray, *scene, options, buf, &box, &note)) {
    if (scene->note.empty()) scene->note = "arm-length image: " + note + "; yaw is not measured";
    return;
  }
  const RegionMoments m = ComputeMoments(buf->arm, box);
  if (scene->side == 0) {
    const double centre_x =
        scene->body_box ? scene->body_box->x + 0.5 * scene->body_box->width
                        : (scene->fixed_shoulder ? scene->fixed_shoulder->x : 0.5 * buf->arm.cols);
    scene->side = m.cx >= centre_x ? 1 : -1;
  }
  const std::optional<cv::Point2d> shoulder = scene->Shoulder(scene->side, options);
  if (!shoulder) return;
  const ArmGeometry g = AnalyzeArm(buf->arm, box, *shoulder, options);
  if (g.found) scene->ref_major_px = g.axes.major;
}

}  // namespace armmimic::bgsub
