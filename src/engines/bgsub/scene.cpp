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
namespace {

cv::Rect Expand(const cv::Rect& r, double fraction, const cv::Size& limit) {
  const int dx = static_cast<int>(r.width * fraction), dy = static_cast<int>(r.height * fraction);
  return cv::Rect(r.x - dx, r.y - dy, r.width + 2 * dx, r.height + 2 * dy) &
         cv::Rect(0, 0, limit.width, limit.height);
}

// The torso edge, in arm half-widths inward of the shoulder (the hanging arm's inner edge).
constexpr double kTorsoMargin = 1.0;

}  // namespace

std::optional<cv::Point2d> SceneModel::Shoulder(int arm_side, const BgsubOptions& options) const {
  if (fixed_shoulder) return fixed_shoulder;
  if (arm_shoulder && !options.thesis_mode && options.shoulder_from_arm_length) return arm_shoulder;
  if (!body_box || arm_side == 0) return std::nullopt;
  const cv::Rect& b = *body_box;
  const double fx = arm_side > 0 ? 1.0 - options.shoulder_side : options.shoulder_side;
  return cv::Point2d(b.x + fx * b.width, b.y + (1.0 - options.shoulder_height) * b.height);
}

double SceneModel::ArmLengthScale() const {
  if (std::isfinite(ref_reach_px) && ref_reach_px > 0) return ref_reach_px;
  if (body_box) return 0.5 * body_box->height;
  return 0.25 * std::max(background.cols, background.rows);
}

bool SceneModel::ArmAtRest(const cv::Point2d& shoulder, const BgsubOptions& options,
                           const Buffers& buf) const {
  if (!(ref_reach_px > 0) || !(arm_half_width_px > 0)) return false;
  const cv::Point2d dir = DirectionVector(options.rest_deg);
  const double upper = options.upper_arm_fraction * ref_reach_px;
  const double r = arm_half_width_px;
  // Pixels along the rest upper arm, from one arm radius below the shoulder to the elbow.
  int total = 0, changed = 0;
  for (double t = r; t <= upper - r; t += 1.0) {
    for (double w = -r; w <= r; w += 1.0) {
      const int x = cvRound(shoulder.x + dir.x * t - dir.y * w);
      const int y = cvRound(shoulder.y + dir.y * t + dir.x * w);
      if (x < 0 || y < 0 || x >= buf.moved.cols || y >= buf.moved.rows) continue;
      ++total;
      if (buf.moved.at<uchar>(y, x)) ++changed;
    }
  }
  return total > 0 && changed < 0.2 * total;
}

double SceneModel::UpperArmFromPerson(const cv::Point2d& shoulder, int arm_side,
                                      const BgsubOptions& options, Buffers* buf) const {
  if (!(ref_reach_px > 0) || !(arm_half_width_px > 0) || arm_side == 0 || buf->person.empty()) {
    return kNaN;
  }
  const double upper = options.upper_arm_fraction * ref_reach_px;
  const int r = static_cast<int>(std::ceil(upper)) + 2;
  const cv::Rect full(0, 0, buf->person.cols, buf->person.rows);
  const cv::Rect roi =
      cv::Rect(cvFloor(shoulder.x) - r, cvFloor(shoulder.y) - r, 2 * r + 1, 2 * r + 1) & full;
  if (roi.area() <= 0) return kNaN;
  buf->person(roi).copyTo(buf->upper_fit);
  // The torso: everything on the inner side of the hanging arm's inner edge.
  const double edge = shoulder.x - arm_side * kTorsoMargin * arm_half_width_px - roi.x;
  for (int y = 0; y < buf->upper_fit.rows; ++y) {
    uchar* row = buf->upper_fit.ptr<uchar>(y);
    if (arm_side > 0) {
      const int end = std::clamp(static_cast<int>(std::ceil(edge)), 0, buf->upper_fit.cols);
      std::fill(row, row + end, uchar{0});
    } else {
      const int begin = std::clamp(static_cast<int>(std::floor(edge)) + 1, 0, buf->upper_fit.cols);
      std::fill(row + begin, row + buf->upper_fit.cols, uchar{0});
    }
  }
  const cv::Point2d origin(shoulder.x - roi.x, shoulder.y - roi.y);
  return RayFit(buf->upper_fit, origin, 0.35 * upper, 0.95 * upper, options.rest_deg + 180, 120);
}

bool FindArmMask(const cv::Mat& gray, const cv::Mat& bgr, const SceneModel& scene,
                 const BgsubOptions& options, bool largest_only, Buffers* buf, cv::Rect* box,
                 std::string* note) {
  const bool improved = !options.thesis_mode;
  // Two-step differencing (5.2.4), optionally after removing a global brightness drift.
  int off_bg = 0, off_still = 0;
  if (improved && options.compensate_drift) {
    const cv::Rect exclude =
        scene.body_box ? Expand(*scene.body_box, 0.25, gray.size()) : cv::Rect();
    off_bg = BrightnessDrift(gray, scene.background, exclude);
    off_still = BrightnessDrift(gray, scene.standstill, exclude);
  }
  // Improved: the arm cannot reach past its length from the shoulder, so only that square is
  // differenced (a third less work at 320x240); the masks are zero elsewhere.
  const cv::Rect full(0, 0, gray.cols, gray.rows);
  cv::Rect search = full;
  const std::optional<cv::Point2d> reach_from = scene.Shoulder(scene.side, options);
  if (improved && !largest_only && reach_from && scene.ref_reach_px > 0) {
    const double r = 1.25 * scene.ref_reach_px + options.closing_size;
    search = cv::Rect(cvFloor(reach_from->x - r), cvFloor(reach_from->y - r), cvCeil(2 * r),
                      cvCeil(2 * r)) &
             full;
  }
  buf->person.create(gray.size(), CV_8UC1);
  buf->moved.create(gray.size(), CV_8UC1);
  if (search != full) {
    buf->person.setTo(0);
    buf->moved.setTo(0);
  }
  cv::Mat person = buf->person(search), moved = buf->moved(search);
  if (improved && options.color_difference && !bgr.empty() && !scene.background_bgr.empty() &&
      !scene.standstill_bgr.empty()) {
    ColorDifferenceMask(bgr(search), scene.background_bgr(search), off_bg, options.threshold,
                        &person);
    ColorDifferenceMask(bgr(search), scene.standstill_bgr(search), off_still, options.threshold,
                        &moved);
  } else {
    DifferenceMask(gray(search), scene.background(search), off_bg, options.threshold, &person);
    DifferenceMask(gray(search), scene.standstill(search), off_still, options.threshold, &moved);
  }
  cv::bitwise_and(buf->person, buf->moved, buf->candidate);
  if (improved && options.reject_shadow && !bgr.empty() && !scene.background_bgr.empty()) {
    cv::Mat candidate = buf->candidate(search);
    RemoveShadow(bgr(search), scene.background_bgr(search), &candidate);
  }

  // Movement of the head: above the shoulders and between them.
  std::optional<cv::Point2d> shoulder = scene.Shoulder(scene.side, options);
  if (improved && options.reject_head && shoulder && std::isfinite(scene.head_cx) &&
      !largest_only) {
    const double half = 0.6 * std::fabs(shoulder->x - scene.head_cx);
    cv::Rect head(static_cast<int>(scene.head_cx - half), 0, static_cast<int>(2 * half),
                  static_cast<int>(shoulder->y));
    head &= cv::Rect(0, 0, gray.cols, gray.rows);
    if (head.area() > 0) buf->candidate(head).setTo(0);
  }

  // Flood-fill connected regions (core MaskComponents).
  buf->components = MaskComponents(buf->candidate, &buf->labels);
  int pick = -1;
  if (largest_only || !improved || !shoulder) {
    pick = LargestComponent(buf->components);
  } else {
    const double radius = options.near_shoulder * scene.ArmLengthScale();
    for (int i = 0; i < static_cast<int>(buf->components.size()); ++i) {
      const Component& c = buf->components[static_cast<std::size_t>(i)];
      if (DistanceToBox(*shoulder, c.box) > radius) continue;
      if (pick < 0 || c.area_px > buf->components[static_cast<std::size_t>(pick)].area_px) pick = i;
    }
  }
  if (pick < 0) {
    *note = buf->components.empty() ? "nothing moved" : "no moving region near the shoulder";
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

void BuildScene(const cv::Mat& arm_length_gray, const cv::Mat& arm_length_bgr,
                const BgsubOptions& options, Buffers* buf, SceneModel* scene) {
  // mask2: the standing body, the largest region of |standstill - background| > threshold.
  DifferenceMask(scene->standstill, scene->background, 0, options.threshold, &buf->person);
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
  if (!FindArmMask(arm_length_gray, arm_length_bgr, *scene, options, /*largest_only=*/true, buf,
                   &box, &note)) {
    if (scene->note.empty()) scene->note = "arm-length image: " + note + "; yaw is not measured";
    return;
  }
  const RegionMoments m = ComputeMoments(buf->arm, box);
  {
    // The head: the top rows of the standing body.
    if (scene->body_box) {
      const cv::Rect& b = *scene->body_box;
      DifferenceMask(scene->standstill, scene->background, 0, options.threshold, &buf->moved);
      const RegionMoments head =
          ComputeMoments(buf->moved, cv::Rect(b.x, b.y, b.width, std::max(1, b.height / 20)));
      if (head.m00 > 0) scene->head_cx = head.cx;
    }
  }
  if (scene->side == 0) {
    const double centre_x =
        scene->body_box ? scene->body_box->x + 0.5 * scene->body_box->width
                        : (scene->fixed_shoulder ? scene->fixed_shoulder->x : 0.5 * buf->arm.cols);
    scene->side = m.cx >= centre_x ? 1 : -1;
  }
  {
    // Where the straight horizontal arm meets the body: its inner end, one arm radius in, at the
    // height of its axis. The hanging arm of the standstill hides the arm's first radius.
    int x_in = box.x + box.width, x_out = box.x - 1;
    for (int y = box.y; y < box.y + box.height; ++y) {
      const uchar* row = buf->arm.ptr<uchar>(y);
      for (int x = box.x; x < box.x + box.width; ++x) {
        if (row[x]) x_in = std::min(x_in, x), x_out = std::max(x_out, x);
      }
    }
    if (x_out >= x_in) {
      const double length = x_out - x_in + 1;
      scene->arm_half_width_px = m.m00 / (2 * length);
      const double inner = scene->side > 0 ? x_in : x_out;
      scene->arm_shoulder = cv::Point2d(inner - scene->side * scene->arm_half_width_px, m.cy);
    }
  }
  const std::optional<cv::Point2d> shoulder = scene->Shoulder(scene->side, options);
  if (!shoulder) return;
  const ArmGeometry g = AnalyzeArm(buf->arm, box, *shoulder, options, /*was_bent=*/false);
  if (!g.found) return;
  scene->ref_major_px = g.axes.major;
  scene->ref_reach_px =
      ReachAlong(g.contour, *shoulder, ResolveDirection(g.axis_deg, *shoulder, {m.cx, m.cy}));
}

}  // namespace armmimic::bgsub
