// RobotPreview: the PUMA arm drawn from its joint angles in a side view (J2 shoulder, J3 elbow)
// and a top view (J1 waist), with the joint limits as arcs. A joint outside its limits is drawn
// red with its value, so a violation is seen before anything moves.
#pragma once

#include <QWidget>

#include "armmimic/robot/limits.h"

namespace armmimic::gui {

class RobotPreview : public QWidget {
  Q_OBJECT
 public:
  explicit RobotPreview(QWidget* parent = nullptr);

  void setLimits(const robot::JointLimits& limits);
  void setPose(const robot::JointArray& joint_deg, const QString& caption);
  const robot::JointArray& pose() const { return pose_; }
  // Joints (0-based) of the current pose outside the limits.
  QList<int> violatingJoints() const;
  QSize sizeHint() const override { return {360, 200}; }
  QSize minimumSizeHint() const override { return {240, 140}; }
  // The widget's rows, top to bottom: the view titles, the two views, the caption (what the
  // pose is: a video frame, the plan, the controller) and the joint values. No two overlap.
  QRectF drawingArea() const;
  QRectF captionArea() const;
  QRectF valuesArea() const;

 protected:
  void paintEvent(QPaintEvent*) override;

 private:
  robot::JointLimits limits_;
  robot::JointArray pose_{0, -90, 0, 0, 0, 0};
  QString caption_;
};

}  // namespace armmimic::gui
