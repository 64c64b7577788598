// ArmView3D: the PUMA arm in 3-D, drawn with OpenGL (QOpenGLWidget): the pose it is given, with
// every part a joint outside its limits moves drawn red, the joint values underneath (red when
// out of limits), the wrist's path over the whole plan, and beside it the person's arm where the
// angle file measured it in 3-D. Drag to orbit, wheel to zoom,
// double-click or Reset view to go back. The arm's geometry and colouring rule are Qt-free
// (armmimic/robot/kinematics.h); this widget only draws them. Where no OpenGL context can be made
// (the offscreen platform, a display without OpenGL) it says so in one line instead, and the
// compact 2-D views show the same pose.
#pragma once

#include <optional>

#include <QMatrix4x4>
#include <QString>
#include <QVector3D>
#include <QWidget>

#include "armmimic/robot/kinematics.h"
#include "armmimic/robot/trajectory.h"

class QLabel;

namespace armmimic::gui {

class ArmGlView;

// Where the view looks from: yaw about the vertical, pitch above the floor, distance to the
// target (the arm's middle). Metres and degrees.
struct ArmCamera {
  static constexpr double kYawDeg = 60;
  static constexpr double kPitchDeg = 15;
  static constexpr double kDistanceM = 3.4;
  double yaw_deg = kYawDeg;
  double pitch_deg = kPitchDeg;
  double distance_m = kDistanceM;
  QVector3D target{0.25f, 0.0f, 0.75f};

  void orbit(double dyaw_deg, double dpitch_deg);  // pitch kept within [-10, 89]
  void zoom(double factor);                        // distance kept within [1.5, 12] m
  void reset() { *this = ArmCamera(); }
  QVector3D eye() const;
  QMatrix4x4 view() const;  // base frame (z up) to camera
};

class ArmView3D : public QWidget {
  Q_OBJECT
 public:
  explicit ArmView3D(QWidget* parent = nullptr);

  // Whether this display gives the view an OpenGL context (checked once per process).
  static bool OpenGlAvailable();
  bool drawsIn3D() const { return gl_ != nullptr; }

  void setLimits(const robot::JointLimits& limits);
  void setPose(const robot::JointArray& joint_deg, const QString& caption);
  // The person's arm measured in 3-D, drawn beside the robot (none: not drawn).
  void setPersonArm(const std::optional<robot::PersonArm>& arm);
  const std::optional<robot::PersonArm>& personArm() const { return person_; }
  // The plan whose wrist path is drawn (empty: none).
  void setPath(const robot::Trajectory& trajectory);
  const robot::JointArray& pose() const { return pose_; }
  const QString& caption() const { return caption_; }
  // Joints (0-based) of the current pose outside the limits: their parts are red.
  QList<int> violatingJoints() const;
  // The joint values under the view ("J1 0.0  J2 -90.0 ..."), as plain text.
  QString valuesText() const;
  // The wrist centre over the plan, base frame, metres (one point per keyframe).
  const std::vector<Eigen::Vector3d>& path() const { return path_; }
  const robot::JointLimits& limits() const { return limits_; }

  ArmCamera& camera() { return camera_; }
  const ArmCamera& camera() const { return camera_; }
  // Orbit, zoom and reset as the mouse does them, then redraw.
  void orbit(double dyaw_deg, double dpitch_deg);
  void zoom(double factor);

  QSize sizeHint() const override { return {360, 260}; }
  QSize minimumSizeHint() const override { return {200, 140}; }

 public slots:
  void resetView();

 signals:
  void viewChanged();

 private:
  void redraw();
  void showTexts();

  ArmGlView* gl_ = nullptr;
  QLabel* fallback_ = nullptr;
  QLabel* caption_label_;
  QLabel* values_label_;
  robot::JointLimits limits_;
  robot::JointArray pose_{0, -90, 0, 0, 0, 0};
  QString caption_;
  std::vector<Eigen::Vector3d> path_;
  std::optional<robot::PersonArm> person_;
  ArmCamera camera_;
};

}  // namespace armmimic::gui
