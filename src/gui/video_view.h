// VideoView: shows one frame with the overlay; zoom (wheel, +/-), pan (drag), and the region of
// interest and shoulder tools, and joint handles to drag (the standstill's estimated joints) on
// the frame they belong to. Knows nothing about engines or files: it draws what it is given.
#pragma once

#include <optional>

#include <QImage>
#include <QWidget>

#include "armmimic/engines/measurement.h"
#include "joint_handles.h"
#include "overlay.h"

namespace armmimic::gui {

class VideoView : public QWidget {
  Q_OBJECT
 public:
  // kJoints: clicks pick the shoulder, the elbow and the wrist in turn.
  enum class Tool { kPan, kRoi, kShoulder, kJoints };

  explicit VideoView(QWidget* parent = nullptr);

  void setFrame(const QImage& image, int frame_index, int frame_count);
  void setMeasurement(const std::optional<ArmMeasurement>& m);
  void setOverlayOptions(const OverlayOptions& options);
  const OverlayOptions& overlayOptions() const { return overlay_; }
  void setRoi(const std::optional<QRect>& roi);
  void setShoulder(const std::optional<QPointF>& shoulder_px);
  const std::optional<QRect>& roi() const { return roi_; }
  const std::optional<QPointF>& shoulder() const { return shoulder_; }
  void setTool(Tool tool);
  Tool tool() const { return tool_; }
  // Handles on the joints of frame `frame`, shown while that frame is: a handle dragged (with
  // any tool) emits jointPicked for all three joints as they then are, as if clicked.
  void setJointHandles(int frame, const JointHandles::Joints& joints_px);
  void clearJointHandles();
  const JointHandles& jointHandles() const { return handles_; }

  const QImage& image() const { return image_; }
  int frameIndex() const { return frame_index_; }
  const std::optional<ArmMeasurement>& measurement() const { return measurement_; }
  OverlayTexts overlayTexts() const;
  // The frame at its own resolution with the overlay painted on it (for "Save frame").
  QImage renderWithOverlay() const;
  // Writes renderWithOverlay() to `path` (format from its suffix). Returns "" or the error,
  // naming the file.
  QString saveWithOverlay(const QString& path) const;
  double zoom() const { return zoom_; }
  // Where the overlay's texts go, in widget pixels: the part of the frame in view.
  QRectF textArea() const;
  // Widget position <-> image pixel.
  QPointF toImage(const QPointF& widget_pos) const;
  QPointF toWidget(const QPointF& image_px) const;

  QSize sizeHint() const override { return {640, 480}; }

 public slots:
  void zoomIn();
  void zoomOut();
  void zoomToFit();

 signals:
  void roiSelected(const QRect& roi_px);
  void shoulderPicked(const QPointF& shoulder_px);
  void jointPicked(int joint, const QPointF& joint_px);  // 0 shoulder, 1 elbow, 2 wrist

 protected:
  void paintEvent(QPaintEvent*) override;
  void wheelEvent(QWheelEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void resizeEvent(QResizeEvent*) override;

 private:
  double fitZoom() const;
  QPointF clampToImage(const QPointF& px) const;
  void zoomAround(double factor, const QPointF& widget_pos);
  QTransform imageToWidget() const;

  QImage image_;
  int frame_index_ = 0;
  int frame_count_ = 0;
  std::optional<ArmMeasurement> measurement_;
  OverlayOptions overlay_;
  std::optional<QRect> roi_;
  std::optional<QPointF> shoulder_;
  Tool tool_ = Tool::kPan;
  int next_joint_ = 0;  // kJoints: the joint the next click picks
  bool fit_ = true;
  double zoom_ = 1.0;
  QPointF offset_;  // widget position of image pixel (0,0)
  bool dragging_ = false;
  QPointF drag_start_;
  QPointF drag_offset_;
  std::optional<QRectF> rubber_;  // ROI being drawn, image pixels
  JointHandles handles_;
  int dragged_joint_ = -1;  // the handle being dragged
};

}  // namespace armmimic::gui
