#include "robot_preview.h"

#include <algorithm>
#include <cmath>

#include <QPainter>
#include <QPainterPath>

namespace armmimic::gui {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
const QColor kOk(0x2a, 0x82, 0xda);
const QColor kBad(0xd0, 0x3b, 0x2f);

}  // namespace

RobotPreview::RobotPreview(QWidget* parent) : QWidget(parent) {
  setObjectName("robotPreview");
  setMinimumSize(240, 140);
}

void RobotPreview::setLimits(const robot::JointLimits& limits) {
  limits_ = limits;
  update();
}

void RobotPreview::setPose(const robot::JointArray& joint_deg, const QString& caption) {
  pose_ = joint_deg;
  caption_ = caption;
  update();
}

QList<int> RobotPreview::violatingJoints() const {
  QList<int> out;
  for (int j = 0; j < robot::kJoints; ++j) {
    if (!limits_.Inside(j, pose_[j])) out << j;
  }
  return out;
}

void RobotPreview::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QPalette pal = palette();
  p.fillRect(rect(), pal.color(QPalette::Base));
  const QColor ink = pal.color(QPalette::Text);
  const QColor faint = pal.color(QPalette::Mid);
  const QList<int> bad = violatingJoints();
  const double w = width() / 2.0;
  const double h = drawingArea().height();
  const double top = drawingArea().top();
  const double link = std::min(w, h) * 0.23;  // upper arm and forearm, same length

  // Side view: the arm in the plane J1 turns. Elevation from hanging = -J2, elbow adds -J3.
  {
    const QPointF shoulder(w * 0.5, top + h * 0.5);
    p.setPen(QPen(faint, 1));
    p.drawText(QRectF(0, 0, w, top), Qt::AlignCenter, tr("side (J2, J3)"));
    p.fillRect(QRectF(shoulder.x() - 6, shoulder.y(), 12, h * 0.5), faint);
    // Limits of J2 as an arc around the shoulder.
    auto arc = [&](const QPointF& c, double r, double a0_deg, double a1_deg, const QColor& col) {
      // Screen angle of "from hanging" a: down is 270 deg in Qt's CCW-from-+x convention.
      QPainterPath path;
      const QRectF box(c.x() - r, c.y() - r, 2 * r, 2 * r);
      path.arcMoveTo(box, 270 + a0_deg);
      path.arcTo(box, 270 + a0_deg, a1_deg - a0_deg);
      p.strokePath(path, QPen(col, 1, Qt::DotLine));
    };
    arc(shoulder, link * 0.4, -limits_.max_deg[1], -limits_.min_deg[1], faint);
    const double e = -pose_[1] * kDeg;               // elevation from hanging, forward positive
    const double f = (-pose_[1] - pose_[2]) * kDeg;  // forearm from hanging
    const QPointF elbow = shoulder + QPointF(std::sin(e), std::cos(e)) * link;
    const QPointF wrist = elbow + QPointF(std::sin(f), std::cos(f)) * link;
    p.setPen(QPen(bad.contains(1) ? kBad : kOk, 6, Qt::SolidLine, Qt::RoundCap));
    p.drawLine(shoulder, elbow);
    p.setPen(QPen(bad.contains(2) ? kBad : kOk.lighter(130), 5, Qt::SolidLine, Qt::RoundCap));
    p.drawLine(elbow, wrist);
    p.setPen(Qt::NoPen);
    p.setBrush(ink);
    p.drawEllipse(shoulder, 4, 4);
    p.drawEllipse(elbow, 3.5, 3.5);
  }
  // Top view: J1 turns the arm's plane about the vertical axis.
  {
    const QPointF base(w * 1.5, top + h * 0.5);
    p.setPen(QPen(faint, 1));
    p.drawText(QRectF(w, 0, w, top), Qt::AlignCenter, tr("top (J1)"));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(base, link * 1.9, link * 1.9);
    const double e = -pose_[1] * kDeg;
    const double f = (-pose_[1] - pose_[2]) * kDeg;
    const double reach = link * (std::sin(e) + std::sin(f));  // horizontal reach, signed
    const double a = pose_[0] * kDeg;
    // J1 = 0 points up the screen (away from the viewer); positive turns counter-clockwise.
    const QPointF dir(-std::sin(a), -std::cos(a));
    for (double lim : {limits_.min_deg[0], limits_.max_deg[0]}) {
      const QPointF d(-std::sin(lim * kDeg), -std::cos(lim * kDeg));
      p.setPen(QPen(faint, 1, Qt::DotLine));
      p.drawLine(base, base + d * link * 1.9);
    }
    p.setPen(QPen(bad.contains(0) ? kBad : kOk, 6, Qt::SolidLine, Qt::RoundCap));
    p.drawLine(base, base + dir * reach);
    p.setPen(Qt::NoPen);
    p.setBrush(ink);
    p.drawEllipse(base, 5, 5);
  }
  // Joint values; out-of-limit ones red.
  const double y = valuesArea().bottom() - fontMetrics().descent();
  double x = 4;
  for (int j = 0; j < robot::kJoints; ++j) {
    const QString t = QString("J%1 %2").arg(j + 1).arg(pose_[j], 0, 'f', 1);
    p.setPen(bad.contains(j) ? kBad : ink);
    p.drawText(QPointF(x, y), t);
    x += fontMetrics().horizontalAdvance(t) + 10;
  }
  if (!caption_.isEmpty()) {
    p.setPen(faint);
    p.drawText(captionArea(), Qt::AlignRight | Qt::AlignVCenter, caption_);
  }
}

QRectF RobotPreview::drawingArea() const {
  const double row = fontMetrics().height();
  return QRectF(0, row, width(), std::max(0.0, height() - 3 * row - 2));
}

QRectF RobotPreview::captionArea() const {
  const double row = fontMetrics().height();
  return QRectF(0, height() - 2 * row - 2, width() - 4, row);
}

QRectF RobotPreview::valuesArea() const {
  const double row = fontMetrics().height();
  return QRectF(0, height() - row - 2, width(), row);
}

}  // namespace armmimic::gui
