// AnglePlot's reading side: zoom, the time axis, the hover readout, the rows in view and saving
// the plot as an image.
#include <algorithm>
#include <cmath>

#include <QBuffer>
#include <QChart>
#include <QFileInfo>
#include <QImage>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QRubberBand>
#include <QSvgGenerator>
#include <QValueAxis>

#include "angle_plot.h"
#include "armmimic/core/output_file.h"

namespace armmimic::gui {
namespace {

QString Deg(double v) {
  return std::isfinite(v) ? QString::number(v, 'f', 1) + QChar(0x00B0) : QString(QChar(0x2014));
}

}  // namespace

void AnglePlot::zoomTo(double first_frame, double last_frame, double low_deg, double high_deg) {
  if (!(last_frame - first_frame >= 1) || !(high_deg - low_deg >= 0.5)) return;  // too small
  zoom_ = QRectF(QPointF(first_frame, low_deg), QPointF(last_frame, high_deg));
  applyRanges();
  emit zoomChanged();
}

void AnglePlot::resetZoom() {
  zoom_.reset();
  applyRanges();
  emit zoomChanged();
}

std::pair<int, int> AnglePlot::visibleFrames() const {
  return {int(std::ceil(frameOf(x_->min()) - 1e-9)), int(std::floor(frameOf(x_->max()) + 1e-9))};
}

std::pair<double, double> AnglePlot::visibleDegrees() const { return {y_->min(), y_->max()}; }

void AnglePlot::setTimeAxis(bool seconds) {
  if (seconds && fps_ <= 0) return;
  seconds_ = seconds;
  applyRanges();
}

QString AnglePlot::readoutAt(int frame) const {
  QString text = tr("frame %1").arg(frame);
  const auto it = std::lower_bound(rows_.begin(), rows_.end(), frame,
                                   [](const AngleRow& r, int f) { return r.frame < f; });
  const AngleRow* row = it != rows_.end() && it->frame == frame ? &*it : nullptr;
  if (row && (fps_ > 0 || row->time_s > 0)) {
    text += QString(" · %1 s").arg(row->time_s, 0, 'f', 3);
  } else if (fps_ > 0) {
    text += QString(" · %1 s").arg(frame / fps_, 0, 'f', 3);
  }
  if (!row) return text + " · " + tr("no measurement");
  if (!row->ok()) return text + " · " + tr("lost");
  const char* names[4] = {"upper", "fore", "yaw", "bend"};
  for (int c = 0; c < 4; ++c) {
    if (c == int(PlotCurve::kYaw) && curveShown(PlotCurve::kYaw) && signUnknown(*row)) {
      text += " · " + tr("yaw +-%1 (sign unknown)").arg(Deg(row->yaw_deg));
    } else if (curveShown(PlotCurve(c))) {
      text += QString(" · %1 %2").arg(tr(names[c]), Deg(valueOf(*row, PlotCurve(c))));
    }
  }
  return text;
}

std::vector<AngleRow> AnglePlot::visibleRows() const {
  const auto [first, last] = visibleFrames();
  std::vector<AngleRow> out;
  for (const AngleRow& row : rows_) {
    if (row.frame >= first && row.frame <= last) out.push_back(row);
  }
  return out;
}

QString AnglePlot::saveImage(const QString& path) {
  const bool cursor_shown = cursor_->isVisible();
  cursor_->setVisible(false);               // the video's position is not part of the data
  const QRect source = viewport()->rect();  // what the widget shows, in its own pixels
  QString error;
  // Drawn in memory, then written through the one output path (a link is followed, a device
  // written to, a folder refused), as every other output.
  QByteArray bytes;
  QBuffer buffer(&bytes);
  buffer.open(QIODevice::WriteOnly);
  if (QFileInfo(path).suffix().compare("svg", Qt::CaseInsensitive) == 0) {
    QSvgGenerator svg;
    svg.setOutputDevice(&buffer);
    svg.setSize(source.size());
    svg.setViewBox(QRectF(QPointF(0, 0), QSizeF(source.size())));
    svg.setTitle(tr("armmimic angles"));
    QPainter painter;
    if (!painter.begin(&svg)) {
      error = tr("%1: cannot write the SVG file").arg(path);
    } else {
      render(&painter, QRectF(QPointF(0, 0), QSizeF(source.size())), source);
      painter.end();
    }
  } else {
    QImage image(source.size() * 2, QImage::Format_ARGB32);
    image.fill(palette().color(QPalette::Base));
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    render(&painter, QRectF(image.rect()), source);
    painter.end();
    if (!image.save(&buffer, "PNG")) error = tr("%1: cannot write the PNG file").arg(path);
  }
  if (error.isEmpty()) {
    const Status st = WriteOutputFile(path.toStdString(), bytes.toStdString());
    if (!st) error = QString::fromStdString(st.message());
  }
  cursor_->setVisible(cursor_shown);
  return error;
}

void AnglePlot::mousePressEvent(QMouseEvent* event) {
  const bool band = event->button() == Qt::RightButton ||
                    (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier));
  if (band) {
    banding_ = true;
    band_origin_ = event->position().toPoint();
    if (!band_) band_ = new QRubberBand(QRubberBand::Rectangle, viewport());
    band_->setGeometry(QRect(band_origin_, QSize()));
    band_->show();
    return;
  }
  if (event->button() == Qt::LeftButton && chart()->plotArea().contains(event->position())) {
    emit frameClicked(frameAt(event->position()));
  }
  QChartView::mousePressEvent(event);
}

void AnglePlot::mouseMoveEvent(QMouseEvent* event) {
  const bool inside = chart()->plotArea().contains(event->position());
  if (banding_) {
    band_->setGeometry(QRect(band_origin_, event->position().toPoint()).normalized());
  } else if ((event->buttons() & Qt::LeftButton) && inside) {
    emit frameClicked(frameAt(event->position()));
  }
  emit hovered(inside ? readoutAt(frameAt(event->position())) : QString());
  QChartView::mouseMoveEvent(event);
}

void AnglePlot::mouseReleaseEvent(QMouseEvent* event) {
  if (!banding_) return QChartView::mouseReleaseEvent(event);
  banding_ = false;
  band_->hide();
  const QRect r = QRect(band_origin_, event->position().toPoint()).normalized();
  if (r.width() > 4 && r.height() > 4) {
    const QPointF a = valueAt(r.topLeft()), b = valueAt(r.bottomRight());
    zoomTo(std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()),
           std::max(a.y(), b.y()));
  } else if (event->button() == Qt::RightButton && !actions().isEmpty()) {
    QMenu::exec(actions(), event->globalPosition().toPoint(), nullptr, this);
  }
}

void AnglePlot::mouseDoubleClickEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton) resetZoom();
}

void AnglePlot::leaveEvent(QEvent* event) {
  emit hovered(QString());
  QChartView::leaveEvent(event);
}

}  // namespace armmimic::gui
