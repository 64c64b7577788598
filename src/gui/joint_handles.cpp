#include "joint_handles.h"

#include <cmath>

namespace armmimic::gui {
namespace {

const QColor kHandle(255, 190, 40);

}  // namespace

void JointHandles::set(int frame, const Joints& joints_px) {
  frame_ = frame;
  joints_ = joints_px;
}

int JointHandles::hit(const QPointF& px, double radius_px) const {
  int best = -1;
  double best_d = radius_px;
  for (int i = 0; i < 3; ++i) {
    const double d = std::hypot(px.x() - joints_[i].x(), px.y() - joints_[i].y());
    if (d <= best_d) {
      best = i;
      best_d = d;
    }
  }
  return best;
}

void JointHandles::paint(QPainter& p, double screen_px) const {
  p.save();
  p.setRenderHint(QPainter::Antialiasing);
  p.setPen(QPen(kHandle, 2 * screen_px, Qt::DashLine));
  p.drawLine(joints_[0], joints_[1]);
  p.drawLine(joints_[1], joints_[2]);
  const char* names[3] = {"S", "E", "W"};
  QFont font = p.font();
  font.setPixelSize(std::max(1, static_cast<int>(std::lround(14 * screen_px))));
  font.setBold(true);
  p.setFont(font);
  const double r = 7 * screen_px;
  for (int i = 0; i < 3; ++i) {
    p.setPen(QPen(Qt::black, 3 * screen_px));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(joints_[i], r, r);
    p.setPen(QPen(kHandle, 2 * screen_px));
    p.drawEllipse(joints_[i], r, r);
    p.drawPoint(joints_[i]);
    // The letter beside its handle, outlined in black to read on any background.
    const QPointF at = joints_[i] + QPointF(r + 2 * screen_px, -r);
    p.setPen(Qt::black);
    for (const QPointF d : {QPointF(-1, 0), QPointF(1, 0), QPointF(0, -1), QPointF(0, 1)}) {
      p.drawText(at + d * screen_px, names[i]);
    }
    p.setPen(kHandle);
    p.drawText(at, names[i]);
  }
  p.restore();
}

}  // namespace armmimic::gui
