// JointHandles: three joints (shoulder, elbow, wrist) of one frame drawn as handles the operator
// can drag: the standstill's estimated joints before a tracking run. The view that owns them
// paints them and passes the mouse on; they know nothing of engines.
#pragma once

#include <array>

#include <QPainter>
#include <QPointF>

namespace armmimic::gui {

class JointHandles {
 public:
  using Joints = std::array<QPointF, 3>;  // 0 shoulder, 1 elbow, 2 wrist; image pixels

  void set(int frame, const Joints& joints_px);
  void clear() { frame_ = -1; }
  bool shownOn(int frame) const { return frame_ >= 0 && frame == frame_; }
  bool empty() const { return frame_ < 0; }
  int frame() const { return frame_; }
  const Joints& joints() const { return joints_; }
  // The joint whose handle is within `radius_px` image pixels of `px` (the nearest), or -1.
  int hit(const QPointF& px, double radius_px) const;
  void move(int joint, const QPointF& px) { joints_.at(joint) = px; }
  // Paints the segments and the handles in image pixels; `screen_px` is one screen pixel.
  void paint(QPainter& painter, double screen_px) const;

 private:
  int frame_ = -1;
  Joints joints_;
};

}  // namespace armmimic::gui
