// The toolbar's icons, drawn as vector glyphs in the palette's colours (no image files).
// Length: GlyphEngine::paint is one switch with a short drawing per icon.
#include "icons.h"

#include <QApplication>
#include <QIconEngine>
#include <QPainter>
#include <QPainterPath>
#include <QPalette>
#include <QPixmap>

namespace armmimic::gui {
namespace {

class GlyphEngine : public QIconEngine {
 public:
  explicit GlyphEngine(IconKind kind) : kind_(kind) {}
  QIconEngine* clone() const override { return new GlyphEngine(kind_); }

  void paint(QPainter* p, const QRect& rect, QIcon::Mode mode, QIcon::State) override {
    const QPalette pal = QApplication::palette();
    QColor ink = mode == QIcon::Disabled ? pal.color(QPalette::Disabled, QPalette::WindowText)
                                         : pal.color(QPalette::Active, QPalette::WindowText);
    const QColor accent = mode == QIcon::Disabled ? ink : QColor(0x2a, 0x82, 0xda);
    const QColor alarm = mode == QIcon::Disabled ? ink : QColor(0xd0, 0x3b, 0x2f);
    p->save();
    p->setRenderHint(QPainter::Antialiasing);
    p->translate(rect.topLeft());
    p->scale(rect.width() / 24.0, rect.height() / 24.0);  // glyphs live in a 24x24 box
    QPen pen(ink, 2.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
    p->setPen(pen);
    p->setBrush(Qt::NoBrush);
    auto tri = [&](QPointF a, QPointF b, QPointF c, const QColor& fill) {
      QPainterPath path;
      path.moveTo(a);
      path.lineTo(b);
      path.lineTo(c);
      path.closeSubpath();
      p->fillPath(path, fill);
    };
    switch (kind_) {
      case IconKind::kOpen:
        p->drawPolyline(QPolygonF({{3, 19}, {3, 6}, {9, 6}, {11, 8}, {19, 8}, {19, 11}}));
        p->drawPolygon(QPolygonF({{3, 19}, {7, 11}, {22, 11}, {18, 19}}));
        break;
      case IconKind::kCamera:
        p->drawRoundedRect(QRectF(2, 7, 20, 13), 2, 2);
        p->drawRect(QRectF(8, 4, 8, 3));
        p->drawEllipse(QPointF(12, 13.5), 4, 4);
        break;
      case IconKind::kPlay:
        tri({7, 4}, {20, 12}, {7, 20}, accent);
        break;
      case IconKind::kPause:
        p->fillRect(QRectF(6, 4, 4, 16), accent);
        p->fillRect(QRectF(14, 4, 4, 16), accent);
        break;
      case IconKind::kStepBack:
        p->fillRect(QRectF(4, 5, 3, 14), ink);
        tri({19, 5}, {8, 12}, {19, 19}, ink);
        break;
      case IconKind::kStepForward:
        p->fillRect(QRectF(17, 5, 3, 14), ink);
        tri({5, 5}, {16, 12}, {5, 19}, ink);
        break;
      case IconKind::kFirst:
        p->fillRect(QRectF(3, 5, 2.5, 14), ink);
        tri({13, 5}, {6, 12}, {13, 19}, ink);
        tri({21, 5}, {14, 12}, {21, 19}, ink);
        break;
      case IconKind::kLast:
        p->fillRect(QRectF(18.5, 5, 2.5, 14), ink);
        tri({3, 5}, {10, 12}, {3, 19}, ink);
        tri({11, 5}, {18, 12}, {11, 19}, ink);
        break;
      case IconKind::kAnalyze:
        p->drawLine(QPointF(5, 20), QPointF(10, 11));
        p->drawLine(QPointF(10, 11), QPointF(18, 6));
        p->setBrush(accent);
        p->drawEllipse(QPointF(10, 11), 2.5, 2.5);
        p->drawEllipse(QPointF(5, 20), 2, 2);
        p->drawEllipse(QPointF(18, 6), 2, 2);
        break;
      case IconKind::kStop:
        p->fillRect(QRectF(5, 5, 14, 14), alarm);
        break;
      case IconKind::kExport:
        p->drawPolyline(QPolygonF({{14, 3}, {5, 3}, {5, 21}, {19, 21}, {19, 8}, {14, 3}}));
        p->drawLine(QPointF(8, 11), QPointF(16, 11));
        p->drawLine(QPointF(8, 14), QPointF(16, 14));
        p->drawLine(QPointF(8, 17), QPointF(13, 17));
        break;
      case IconKind::kSaveImage:
        p->drawRect(QRectF(3, 5, 18, 14));
        p->drawPolyline(QPolygonF({{3, 17}, {9, 11}, {13, 15}, {16, 12}, {21, 17}}));
        p->drawEllipse(QPointF(16, 8.5), 1.5, 1.5);
        break;
      case IconKind::kRoi: {
        QPen dash = pen;
        dash.setStyle(Qt::DashLine);
        dash.setColor(accent);
        p->setPen(dash);
        p->drawRect(QRectF(4, 5, 16, 14));
        break;
      }
      case IconKind::kShoulder:
        p->setPen(QPen(accent, 2.0));
        p->drawEllipse(QPointF(12, 12), 6, 6);
        p->drawLine(QPointF(12, 2), QPointF(12, 22));
        p->drawLine(QPointF(2, 12), QPointF(22, 12));
        break;
      case IconKind::kPan:
        p->drawLine(QPointF(12, 3), QPointF(12, 21));
        p->drawLine(QPointF(3, 12), QPointF(21, 12));
        tri({12, 1}, {9, 5}, {15, 5}, ink);
        tri({12, 23}, {9, 19}, {15, 19}, ink);
        tri({1, 12}, {5, 9}, {5, 15}, ink);
        tri({23, 12}, {19, 9}, {19, 15}, ink);
        break;
      case IconKind::kZoomIn:
      case IconKind::kZoomOut:
      case IconKind::kZoomFit:
        p->drawEllipse(QPointF(10, 10), 6, 6);
        p->drawLine(QPointF(14.5, 14.5), QPointF(21, 21));
        if (kind_ != IconKind::kZoomFit) p->drawLine(QPointF(7, 10), QPointF(13, 10));
        if (kind_ == IconKind::kZoomIn) p->drawLine(QPointF(10, 7), QPointF(10, 13));
        if (kind_ == IconKind::kZoomFit) p->drawRect(QRectF(7.5, 7.5, 5, 5));
        break;
      case IconKind::kBackground:
        p->drawRect(QRectF(3, 4, 18, 16));
        p->fillRect(QRectF(6, 7, 4, 4), ink);
        p->fillRect(QRectF(14, 7, 4, 4), ink);
        p->fillRect(QRectF(6, 13, 4, 4), ink);
        p->fillRect(QRectF(14, 13, 4, 4), accent);
        break;
      case IconKind::kRobot:
      case IconKind::kApp:
        p->drawLine(QPointF(4, 21), QPointF(14, 21));
        p->drawLine(QPointF(9, 21), QPointF(9, 14));
        p->setPen(QPen(accent, 2.5, Qt::SolidLine, Qt::RoundCap));
        p->drawLine(QPointF(9, 14), QPointF(15, 7));
        p->drawLine(QPointF(15, 7), QPointF(21, 11));
        p->setBrush(ink);
        p->setPen(Qt::NoPen);
        p->drawEllipse(QPointF(9, 14), 2, 2);
        p->drawEllipse(QPointF(15, 7), 2, 2);
        break;
      case IconKind::kSend:
        tri({3, 4}, {21, 12}, {3, 20}, accent);
        p->setPen(QPen(pal.color(QPalette::Base), 2.0));
        p->drawLine(QPointF(3, 12), QPointF(11, 12));
        break;
    }
    p->restore();
  }

  QPixmap pixmap(const QSize& size, QIcon::Mode mode, QIcon::State state) override {
    QPixmap pm(size);
    pm.fill(Qt::transparent);
    QPainter p(&pm);
    paint(&p, QRect(QPoint(0, 0), size), mode, state);
    return pm;
  }

  QPixmap scaledPixmap(const QSize& size, QIcon::Mode mode, QIcon::State state,
                       qreal scale) override {
    QPixmap pm(size * scale);
    pm.fill(Qt::transparent);
    {
      QPainter p(&pm);
      paint(&p, QRect(QPoint(0, 0), size * scale), mode, state);
    }
    pm.setDevicePixelRatio(scale);
    return pm;
  }

 private:
  IconKind kind_;
};

}  // namespace

QIcon MakeIcon(IconKind kind) { return QIcon(new GlyphEngine(kind)); }

}  // namespace armmimic::gui
