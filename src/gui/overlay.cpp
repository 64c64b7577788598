// The video overlay: the engine's shapes (contour, hull, parts, joints) and its texts.
// Length: PaintOverlayShapes draws each optional layer in turn, sharing the painter's unit and
// pens.
#include "overlay.h"

#include "armmimic/engines/pose.h"
#include "score_labels.h"

#include <algorithm>
#include <cmath>

#include <QFont>
#include <QFontMetricsF>
#include <QPainterPath>

namespace armmimic::gui {
namespace {

QString Deg(double v) {
  if (std::isnan(v)) return QStringLiteral("—");
  return QString::number(v, 'f', 1) + QChar(0x00B0);
}

// A signed angle with its sign spelled out ("+12.3°", "-4.0°").
QString SignedDeg(double v) {
  if (std::isnan(v)) return Deg(v);
  return (v >= 0 ? QStringLiteral("+") : QString()) + Deg(v);
}

bool Finite(const cv::Point2d& p) { return std::isfinite(p.x) && std::isfinite(p.y); }
QPointF Q(const cv::Point2d& p) { return QPointF(p.x, p.y); }

const QColor kUpper(255, 196, 0);
const QColor kFore(0, 200, 255);
const QColor kJoint(255, 64, 64);
const QColor kMarker(80, 255, 80);
const QColor kAxis(255, 0, 220);  // the marker joint's fitted cylinder

// Text with a dark halo so it reads over any video.
void HaloText(QPainter& p, const QPointF& baseline, const QString& text, const QColor& color) {
  QPainterPath path;
  path.addText(baseline, p.font(), text);
  p.strokePath(path, QPen(QColor(0, 0, 0, 200), std::max(2.0, p.font().pointSizeF() / 4.0)));
  p.fillPath(path, color);
}

// The marker engine names the image of every view it measures.
bool IsMarkerView(const ArmMeasurement& m) { return !m.file.empty(); }

}  // namespace

OverlayTexts MakeOverlayTexts(const ArmMeasurement* m, int frame_index, int frame_count) {
  OverlayTexts t;
  t.frame = frame_count > 0 ? QString("frame %1 / %2").arg(frame_index).arg(frame_count - 1)
                            : QString("frame %1").arg(frame_index);
  if (!m) {
    t.yaw = "yaw " + Deg(kNaN);
    t.orientation = "upper " + Deg(kNaN) + "  fore " + Deg(kNaN);
    t.state = "not analysed";
    return t;
  }
  // The marker engine's yaw has a sign: positive turns the joint's right side to the camera.
  // A marker view whose sign could not be told says so instead of showing the yaw as positive.
  t.yaw = !std::isnan(m->yaw_signed_deg) ? "yaw " + SignedDeg(m->yaw_signed_deg)
          : IsMarkerView(*m) && m->phase == MeasurementPhase::kOk && std::isfinite(m->yaw_deg)
              ? "yaw +-" + Deg(m->yaw_deg) + " (sign unknown)"
              : "yaw " + Deg(m->yaw_deg);
  if (IsMarkerView(*m)) {
    t.orientation = "bend " + Deg(m->bend_deg);  // the 2-DOF joint has no arm segments
  } else {
    t.orientation = "upper " + Deg(m->upper_deg) + "  fore " + Deg(m->fore_deg);
    if (!std::isnan(m->bend_deg)) t.orientation += "  bend " + Deg(m->bend_deg);
  }
  switch (m->phase) {
    case MeasurementPhase::kOk:
      t.state = "ok";
      break;
    case MeasurementPhase::kSetup:
      t.state = "setup";
      break;
    case MeasurementPhase::kLost:
      t.state = "lost";
      break;
  }
  if (!m->note.empty()) t.state += ": " + QString::fromStdString(m->note);
  if (m->phase == MeasurementPhase::kOk && std::isfinite(m->confidence)) {
    t.state +=
        (m->note.empty() ? ": " : "; ") + QString("confidence %1").arg(m->confidence, 0, 'f', 2);
  }
  return t;
}

double OverlayUnit(QSize image_size) { return std::max(1.0, image_size.height() / 240.0); }

void PaintOverlay(QPainter& p, QSize image_size, const ArmMeasurement* m, int frame_index,
                  int frame_count, const OverlayOptions& o) {
  PaintOverlayShapes(p, image_size, m, o);
  PaintOverlayTexts(p, QRectF(QPointF(0, 0), QSizeF(image_size)), OverlayUnit(image_size), m,
                    frame_index, frame_count, o);
}

// The pose engine's 17 keypoints: bones between keypoints both scored 0.2 or more, each keypoint
// a dot with its score beside it (grey below 0.2, where the network does not see it).
void PaintSkeleton(QPainter& p, const ArmMeasurement& m, double unit) {
  if (m.pose_keypoints.size() != kPoseKeypointCount || m.pose_scores.size() != kPoseKeypointCount) {
    return;
  }
  constexpr double kSeen = 0.2;
  p.setBrush(Qt::NoBrush);
  p.setPen(QPen(QColor(120, 230, 255, 200), 1.2 * unit, Qt::SolidLine, Qt::RoundCap));
  for (const auto& [a, b] : kPoseBones) {
    if (m.pose_scores[a] >= kSeen && m.pose_scores[b] >= kSeen) {
      p.drawLine(Q(m.pose_keypoints[a]), Q(m.pose_keypoints[b]));
    }
  }
  QFont font = p.font();
  font.setPointSizeF(5.0 * unit);
  p.setFont(font);
  std::vector<QPointF> dots;
  std::vector<double> scores;
  for (int i = 0; i < kPoseKeypointCount; ++i) {
    dots.push_back(Q(m.pose_keypoints[i]));
    scores.push_back(m.pose_scores[i]);
  }
  const auto labels = PlaceScoreLabels(dots, scores, QFontMetricsF(font, p.device()), unit);
  for (int i = 0; i < kPoseKeypointCount; ++i) {
    const bool seen = m.pose_scores[i] >= kSeen;
    const QColor colour = seen ? QColor(120, 230, 255) : QColor(150, 150, 150);
    p.setPen(Qt::NoPen);
    p.setBrush(colour);
    p.drawEllipse(dots[i], 1.8 * unit, 1.8 * unit);
    p.setBrush(Qt::NoBrush);
    if (labels[i]) HaloText(p, labels[i]->baseline, labels[i]->text, colour);
  }
}

namespace {

// One arm's segments, centres of mass, elbow and shoulder.
void PaintArm(QPainter& p, const ArmMeasurement& m, const OverlayOptions& o, double unit) {
  if (o.segments && m.shoulder_px && m.elbow_px) {
    p.setPen(QPen(kUpper, 2 * unit, Qt::SolidLine, Qt::RoundCap));
    p.drawLine(Q(*m.shoulder_px), Q(*m.elbow_px));
    if (m.wrist_px) {
      p.setPen(QPen(kFore, 2 * unit, Qt::SolidLine, Qt::RoundCap));
      p.drawLine(Q(*m.elbow_px), Q(*m.wrist_px));
    }
  }
  if (o.centres) {
    p.setBrush(Qt::NoBrush);
    if (Finite(m.upper_com_px)) {
      p.setPen(QPen(kUpper, 1.5 * unit));
      p.drawEllipse(Q(m.upper_com_px), 4 * unit, 4 * unit);
    }
    if (Finite(m.fore_com_px)) {
      p.setPen(QPen(kFore, 1.5 * unit));
      p.drawEllipse(Q(m.fore_com_px), 4 * unit, 4 * unit);
    }
  }
  if (o.elbow && m.elbow_px) {
    p.setPen(Qt::NoPen);
    p.setBrush(kJoint);
    p.drawEllipse(Q(*m.elbow_px), 3 * unit, 3 * unit);
  }
  if (o.shoulder && m.shoulder_px) {
    p.setPen(QPen(kJoint, 1.5 * unit));
    p.setBrush(Qt::NoBrush);
    const QPointF s = Q(*m.shoulder_px);
    p.drawRect(QRectF(s - QPointF(3.5 * unit, 3.5 * unit), QSizeF(7 * unit, 7 * unit)));
  }
}

}  // namespace

void PaintOverlayShapes(QPainter& p, QSize image_size, const ArmMeasurement* m,
                        const OverlayOptions& o) {
  p.save();
  p.setRenderHint(QPainter::Antialiasing);
  const double unit = OverlayUnit(image_size);
  if (m) {
    if (o.contour && m->arm_contour.size() > 2) {
      QPolygonF poly;
      for (const auto& pt : m->arm_contour) poly << QPointF(pt.x + 0.5, pt.y + 0.5);
      p.setPen(QPen(QColor(255, 255, 255, 160), unit));
      p.drawPolygon(poly);
      if (m->arm_hull.size() > 2) {
        QPolygonF hull;
        for (const auto& pt : m->arm_hull) hull << QPointF(pt.x + 0.5, pt.y + 0.5);
        p.setPen(QPen(QColor(255, 255, 255, 110), unit, Qt::DashLine));
        p.drawPolygon(hull);
      }
    }
    if (o.contour && m->body_box) {
      const cv::Rect& b = *m->body_box;
      p.setPen(QPen(QColor(200, 200, 200, 160), unit, Qt::DotLine));
      p.drawRect(QRectF(b.x, b.y, b.width, b.height));
    }
    if (o.markers) {
      p.setPen(QPen(QColor(255, 255, 0), unit));
      p.setBrush(Qt::NoBrush);
      for (const cv::Rect& r : m->candidate_boxes) p.drawRect(QRectF(r.x, r.y, r.width, r.height));
      p.setPen(QPen(kMarker, 1.5 * unit));
      for (std::size_t i = 0; i < m->marker_centres.size(); ++i) {
        if (!Finite(m->marker_centres[i])) continue;  // a marker not measured in this view
        const QPointF c = Q(m->marker_centres[i]);
        p.drawLine(c - QPointF(4 * unit, 0), c + QPointF(4 * unit, 0));
        p.drawLine(c - QPointF(0, 4 * unit), c + QPointF(0, 4 * unit));
      }
      if (m->marker_centres.size() >= 3) {
        p.setPen(QPen(kMarker, unit, Qt::DashLine));
        for (int i : {1, 2}) {
          if (Finite(m->marker_centres[0]) && Finite(m->marker_centres[i])) {
            p.drawLine(Q(m->marker_centres[0]), Q(m->marker_centres[i]));
          }
        }
      }
      // The lower part's fitted cylinder: its silhouette and, bolder, its axis up to the pivot.
      if (m->cylinder_edges_px.size() == 4) {
        p.setPen(QPen(kAxis, 0.75 * unit, Qt::DotLine));
        p.drawLine(Q(m->cylinder_edges_px[0]), Q(m->cylinder_edges_px[1]));
        p.drawLine(Q(m->cylinder_edges_px[2]), Q(m->cylinder_edges_px[3]));
      }
      if (m->cylinder_axis_px.size() == 2) {
        p.setPen(QPen(kAxis, 1.5 * unit, Qt::DashDotLine));
        p.drawLine(Q(m->cylinder_axis_px[0]), Q(m->cylinder_axis_px[1]));
      }
    }
    if (o.features) {
      p.setPen(Qt::NoPen);
      p.setBrush(kUpper);
      for (const auto& f : m->upper_features) p.drawEllipse(QPointF(f.x, f.y), unit, unit);
      p.setBrush(kFore);
      for (const auto& f : m->fore_features) p.drawEllipse(QPointF(f.x, f.y), unit, unit);
      p.setBrush(Qt::NoBrush);
    }
    if (o.skeleton) PaintSkeleton(p, *m, unit);
    for (const ArmMeasurement* arm : m->Arms()) PaintArm(p, *arm, o, unit);
  }
  p.restore();
}

void PaintOverlayTexts(QPainter& p, const QRectF& area, double unit, const ArmMeasurement* m,
                       int frame_index, int frame_count, const OverlayOptions& o) {
  p.save();
  p.setRenderHint(QPainter::Antialiasing);
  if (m) m = &m->Arm(static_cast<std::size_t>(o.arm));  // the texts are about the arm picked
  const OverlayTexts texts = MakeOverlayTexts(m, frame_index, frame_count);
  QFont font = p.font();
  font.setPointSizeF(8.0 * unit);
  font.setBold(true);
  p.setFont(font);
  const QFontMetricsF fm(font);
  const double margin = 4 * unit;
  const double x0 = area.left() + margin;
  const double x1 = area.right() - margin;
  const double y0 = area.top() + margin;
  const double y1 = area.bottom() - margin;
  const double ymid = area.center().y();
  if (o.frame_count) HaloText(p, QPointF(x0, y0 + fm.ascent()), texts.frame, Qt::white);
  if (m && o.yaw) {
    HaloText(p, QPointF(x1 - fm.horizontalAdvance(texts.yaw), ymid), texts.yaw, Qt::white);
  }
  if (m && o.orientation && IsMarkerView(*m)) {
    const QString bend = "bend " + Deg(m->bend_deg);
    HaloText(p, QPointF(x1 - fm.horizontalAdvance(bend), y1 - fm.descent()), bend, kMarker);
  } else if (m && o.orientation) {
    const QString upper = "upper " + Deg(m->upper_deg);
    const QString fore = "fore " + Deg(m->fore_deg);
    const double y2 = y1 - fm.descent();
    HaloText(p, QPointF(x1 - fm.horizontalAdvance(fore), y2), fore, kFore);
    HaloText(p, QPointF(x1 - fm.horizontalAdvance(upper), y2 - fm.height()), upper, kUpper);
  }
  if (m && m->phase == MeasurementPhase::kLost) {
    HaloText(p, QPointF(x0, y1 - fm.descent()), "lost", QColor(255, 90, 90));
  }
  p.restore();
}

}  // namespace armmimic::gui
