#include "video_view.h"

#include <QBuffer>
#include <QFileInfo>

#include <algorithm>
#include <cmath>

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include "armmimic/core/output_file.h"

namespace armmimic::gui {

VideoView::VideoView(QWidget* parent) : QWidget(parent) {
  setObjectName("videoView");
  setMouseTracking(true);
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(320, 240);
  setAutoFillBackground(false);
}

void VideoView::setFrame(const QImage& image, int frame_index, int frame_count) {
  const bool size_changed = image.size() != image_.size();
  image_ = image;
  frame_index_ = frame_index;
  frame_count_ = frame_count;
  if (size_changed) zoomToFit();
  update();
}

void VideoView::setMeasurement(const std::optional<ArmMeasurement>& m) {
  measurement_ = m;
  update();
}

void VideoView::setOverlayOptions(const OverlayOptions& options) {
  overlay_ = options;
  update();
}

void VideoView::setRoi(const std::optional<QRect>& roi) {
  roi_ = roi;
  update();
}

void VideoView::setShoulder(const std::optional<QPointF>& shoulder_px) {
  shoulder_ = shoulder_px;
  update();
}

void VideoView::setTool(Tool tool) {
  next_joint_ = 0;
  tool_ = tool;
  setCursor(tool == Tool::kPan ? Qt::OpenHandCursor : Qt::CrossCursor);
}

void VideoView::setJointHandles(int frame, const JointHandles::Joints& joints_px) {
  handles_.set(frame, joints_px);
  dragged_joint_ = -1;
  update();
}

void VideoView::clearJointHandles() {
  handles_.clear();
  dragged_joint_ = -1;
  update();
}

OverlayTexts VideoView::overlayTexts() const {
  const ArmMeasurement* m =
      measurement_ ? &measurement_->Arm(static_cast<std::size_t>(overlay_.arm)) : nullptr;
  return MakeOverlayTexts(m, frame_index_, frame_count_);
}

QImage VideoView::renderWithOverlay() const {
  QImage out = image_.convertToFormat(QImage::Format_RGB32);
  if (out.isNull()) return out;
  QPainter p(&out);
  PaintOverlay(p, out.size(), measurement_ ? &*measurement_ : nullptr, frame_index_, frame_count_,
               overlay_);
  return out;
}

double VideoView::fitZoom() const {
  if (image_.isNull()) return 1.0;
  return std::min(width() / double(image_.width()), height() / double(image_.height()));
}

QTransform VideoView::imageToWidget() const {
  return QTransform::fromTranslate(offset_.x(), offset_.y()).scale(zoom_, zoom_);
}

QPointF VideoView::toImage(const QPointF& pos) const { return (pos - offset_) / zoom_; }
QPointF VideoView::toWidget(const QPointF& px) const { return px * zoom_ + offset_; }

void VideoView::zoomToFit() {
  fit_ = true;
  zoom_ = fitZoom();
  offset_ =
      QPointF((width() - image_.width() * zoom_) / 2, (height() - image_.height() * zoom_) / 2);
  update();
}

void VideoView::zoomAround(double factor, const QPointF& pos) {
  if (image_.isNull()) return;
  const QPointF px = toImage(pos);
  zoom_ = std::clamp(zoom_ * factor, 0.05, 40.0);
  offset_ = pos - px * zoom_;
  fit_ = false;
  update();
}

void VideoView::zoomIn() { zoomAround(1.25, rect().center()); }
void VideoView::zoomOut() { zoomAround(0.8, rect().center()); }

void VideoView::resizeEvent(QResizeEvent*) {
  if (fit_) zoomToFit();
}

void VideoView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), palette().color(QPalette::Dark));
  if (image_.isNull()) {
    p.setPen(palette().color(QPalette::BrightText));
    p.drawText(rect(), Qt::AlignCenter,
               tr("Open a video (Ctrl+O), drop a file here,\nor capture from a camera."));
    return;
  }
  p.setTransform(imageToWidget());
  p.setRenderHint(QPainter::SmoothPixmapTransform, zoom_ < 1.0);
  p.drawImage(QPointF(0, 0), image_);
  const ArmMeasurement* m = measurement_ ? &*measurement_ : nullptr;
  PaintOverlayShapes(p, image_.size(), m, overlay_);
  const double px = 1.0 / zoom_;  // one screen pixel in image units
  if (roi_) {
    p.setPen(QPen(QColor(42, 130, 218), 2 * px, Qt::DashLine));
    p.setBrush(Qt::NoBrush);
    p.drawRect(QRectF(*roi_));
  }
  if (rubber_) {
    p.setPen(QPen(QColor(255, 255, 255), 1.5 * px, Qt::DashLine));
    p.drawRect(*rubber_);
  }
  if (shoulder_) {
    p.setPen(QPen(QColor(42, 130, 218), 2 * px));
    p.drawEllipse(*shoulder_, 6 * px, 6 * px);
    p.drawLine(*shoulder_ - QPointF(10 * px, 0), *shoulder_ + QPointF(10 * px, 0));
    p.drawLine(*shoulder_ - QPointF(0, 10 * px), *shoulder_ + QPointF(0, 10 * px));
  }
  if (handles_.shownOn(frame_index_)) handles_.paint(p, px);
  // The texts at the corners of the part of the frame in view, at their size when the frame
  // fits: zoomed in or panned, the frame count, yaw and angles stay on screen and readable.
  p.resetTransform();
  PaintOverlayTexts(p, textArea(), OverlayUnit(image_.size()) * std::min(zoom_, fitZoom()), m,
                    frame_index_, frame_count_, overlay_);
}

QRectF VideoView::textArea() const {
  if (image_.isNull()) return QRectF();
  return imageToWidget().mapRect(QRectF(image_.rect())).intersected(QRectF(rect()));
}

void VideoView::wheelEvent(QWheelEvent* event) {
  const double steps = event->angleDelta().y() / 120.0;
  if (steps != 0) zoomAround(std::pow(1.2, steps), event->position());
  event->accept();
}

void VideoView::mousePressEvent(QMouseEvent* event) {
  if (image_.isNull()) return;
  const QPointF px = toImage(event->position());
  if (event->button() == Qt::LeftButton && handles_.shownOn(frame_index_)) {
    dragged_joint_ = handles_.hit(px, 10 / zoom_);  // within 10 screen pixels
    if (dragged_joint_ >= 0) return;
  }
  if (event->button() == Qt::MiddleButton ||
      (event->button() == Qt::LeftButton && tool_ == Tool::kPan)) {
    dragging_ = true;
    drag_start_ = event->position();
    drag_offset_ = offset_;
    setCursor(Qt::ClosedHandCursor);
  } else if (event->button() == Qt::LeftButton && tool_ == Tool::kRoi) {
    rubber_ = QRectF(px, px);
  } else if (event->button() == Qt::LeftButton &&
             (tool_ == Tool::kShoulder || tool_ == Tool::kJoints)) {
    const QPointF clamped = clampToImage(px);
    const int joint = tool_ == Tool::kJoints ? next_joint_ : 0;
    if (joint == 0) shoulder_ = clamped;
    update();
    if (tool_ == Tool::kShoulder) {
      emit shoulderPicked(clamped);
    } else {
      next_joint_ = (next_joint_ + 1) % 3;
      emit jointPicked(joint, clamped);
    }
  }
}

QPointF VideoView::clampToImage(const QPointF& px) const {
  return QPointF(std::clamp(px.x(), 0.0, image_.width() - 1.0),
                 std::clamp(px.y(), 0.0, image_.height() - 1.0));
}

void VideoView::mouseMoveEvent(QMouseEvent* event) {
  if (dragged_joint_ >= 0) {
    handles_.move(dragged_joint_, clampToImage(toImage(event->position())));
    update();
  } else if (dragging_) {
    offset_ = drag_offset_ + (event->position() - drag_start_);
    fit_ = false;
    update();
  } else if (rubber_) {
    rubber_->setBottomRight(toImage(event->position()));
    update();
  }
}

void VideoView::mouseReleaseEvent(QMouseEvent* event) {
  if (dragged_joint_ >= 0) {
    handles_.move(dragged_joint_, clampToImage(toImage(event->position())));
    dragged_joint_ = -1;
    update();
    // The three joints as they now stand, as if clicked in turn.
    for (int joint = 0; joint < 3; ++joint) emit jointPicked(joint, handles_.joints()[joint]);
    return;
  }
  if (dragging_) {
    dragging_ = false;
    setCursor(tool_ == Tool::kPan ? Qt::OpenHandCursor : Qt::CrossCursor);
    return;
  }
  if (rubber_) {
    rubber_->setBottomRight(toImage(event->position()));
    const QRect r = rubber_->normalized().toAlignedRect().intersected(image_.rect());
    rubber_.reset();
    if (r.width() >= 4 && r.height() >= 4) {
      roi_ = r;
      emit roiSelected(r);
    }
    update();
  }
}

}  // namespace armmimic::gui

namespace armmimic::gui {

QString VideoView::saveWithOverlay(const QString& path) const {
  const QImage image = renderWithOverlay();
  if (image.isNull()) return tr("No frame to save: open a video first");
  // Encoded in memory, then written through the one output path (a link is followed, a device
  // written to, a folder refused), as every other output.
  QByteArray bytes;
  QBuffer buffer(&bytes);
  const QByteArray format = QFileInfo(path).suffix().toLower().toLatin1();
  if (!buffer.open(QIODevice::WriteOnly) ||
      !image.save(&buffer, format.isEmpty() ? "png" : format.constData())) {
    return tr("%1: cannot save the frame: no image writer for this file type").arg(path);
  }
  const Status st = WriteOutputFile(path.toStdString(), bytes.toStdString());
  return st ? QString() : QString::fromStdString(st.message());
}

}  // namespace armmimic::gui
