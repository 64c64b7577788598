// AnglePlot: upper arm, forearm and yaw against the frame or the time (Qt Charts); for the marker
// engine's views, yaw and bend. A curve is drawn only through consecutive measured frames: a
// lost frame, or a value not measured, leaves a gap, and lost frames are shaded red with a mark
// along the bottom. The video cursor is a dashed vertical line; a click seeks to that frame.
// Hovering reads out the frame, time and values; dragging with the right button (or with Shift)
// zooms to a rectangle, a double-click shows everything again. The plot saves itself as PNG or
// SVG, and the rows of the frames in view as CSV.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <QChartView>

#include "armmimic/core/angle_csv.h"
#include "result_store.h"

class QGraphicsLineItem;
class QGraphicsRectItem;
class QLineSeries;
class QRubberBand;
class QScatterSeries;
class QValueAxis;

namespace armmimic::gui {

enum class PlotCurve { kUpper = 0, kFore = 1, kYaw = 2, kBend = 3 };

class PlotLayer;

class AnglePlot : public QChartView {
  Q_OBJECT
 public:
  explicit AnglePlot(QWidget* parent = nullptr);

  // The video's frames (0 .. count-1) and rate; fps <= 0 (still images) allows no time axis.
  void setFrameRange(int frame_count, double fps = 0);
  // Rebuilds the curves from `results` (called on the window's throttle timer); with two arms
  // measured (the pose engine's side both), those of arm `arm` (0 the left, 1 the right).
  void setResults(const ResultStore& results, int arm = 0);
  void setCursorFrame(int frame);
  int cursorFrame() const { return cursor_frame_; }
  int pointCount() const;  // measured frames on the upper-arm curve, for tests
  int lostCount() const;
  int bendCount() const;             // measured frames on the bend curve (marker views)
  bool yawShown() const;             // the yaw curve and its legend entry
  QList<QPointF> yawPoints() const;  // (frame, yaw) drawn: signed for marker views
  // The largest change in degrees along one drawn segment of `curve` (a curve crossing ±180° is
  // broken at the edge, so never more than 180).
  double largestStepDeg(PlotCurve curve) const;
  // (frame, |yaw|) of the marker views whose yaw sign is unknown: drawn apart, at +-|yaw|.
  QList<QPointF> unsignedYawPoints() const;
  // The row of `frame` has a yaw but its sign could not be told (a signed-yaw file only).
  bool signUnknown(const AngleRow& row) const;
  // Runs of consecutive frames a curve is drawn through, as (first, last) frame pairs.
  std::vector<std::pair<int, int>> runs(PlotCurve curve) const;
  // The frame axis' label step: 1, 2, 5, 10, 20, ... so that every label is a whole frame (in
  // seconds on a time axis: 0.1, 0.2, 0.5, 1, ...).
  double frameTickStep() const;
  // Labels on the degree axis: every 45° when the plot is tall enough, else every 60°, 90° or
  // 180°, so that no label is cut to "...".
  int degreeTickCount() const;
  // Frame under a widget position (rounded), for clicks.
  int frameAt(const QPointF& widget_pos) const;

  // Zoom to frames [first, last] and degrees [low, high]; resetZoom() shows everything.
  void zoomTo(double first_frame, double last_frame, double low_deg, double high_deg);
  void resetZoom();
  bool isZoomed() const { return zoom_.has_value(); }
  // The whole frames in view, (first, last).
  std::pair<int, int> visibleFrames() const;
  // Degrees in view, (low, high).
  std::pair<double, double> visibleDegrees() const;
  void setTimeAxis(bool seconds);
  bool timeAxis() const { return seconds_; }
  bool canShowTime() const { return fps_ > 0; }

  // "frame 12 · 0.400 s · upper -45.0° · fore -30.0° · yaw 10.0°", "frame 13 · 0.433 s · lost".
  QString readoutAt(int frame) const;
  // The angle-file rows of the frames in view, for "save range as CSV".
  std::vector<AngleRow> visibleRows() const;
  bool hasFileColumn() const { return file_column_; }
  // Writes the plot as it is shown (without the video cursor) to `path`: SVG for ".svg", else a
  // PNG at twice the widget's size. Returns "" or what went wrong, naming the file.
  QString saveImage(const QString& path);

 signals:
  void frameClicked(int frame);
  // The readout under the mouse ("" when it leaves the plot).
  void hovered(const QString& readout);
  void zoomChanged();

 protected:
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void leaveEvent(QEvent* event) override;
  // A switch between the dark and the light scheme while running repaints the chart in it.
  void changeEvent(QEvent* event) override;

 private:
  void applyTheme();
  void applyRanges();
  void fitDegreeTicks(const QRectF& plot_area);
  void redrawLayers();
  double xOf(double frame) const;
  double frameOf(double x) const;
  QPointF toChart(double frame, double deg) const;   // chart item coordinates
  QPointF valueAt(const QPointF& widget_pos) const;  // (frame, degrees)
  double valueOf(const AngleRow& row, PlotCurve curve) const;
  bool curveShown(PlotCurve curve) const;

  QLineSeries* legend_[4];  // empty series: the legend entries and the axes' domain
  QScatterSeries* lost_;    // legend entry of the lost frames
  QValueAxis* x_;
  QValueAxis* y_;
  QGraphicsRectItem* clip_;  // the plot area; clips the layers below
  PlotLayer* curve_items_[4];
  PlotLayer* lost_bands_;
  PlotLayer* lost_ticks_;
  PlotLayer* unsigned_yaw_;  // marks of the yaws whose sign is unknown
  QGraphicsLineItem* cursor_;
  QRubberBand* band_ = nullptr;
  QPoint band_origin_;
  bool banding_ = false;

  std::vector<AngleRow> rows_;  // ok and lost rows, by frame
  bool file_column_ = false;    // marker views: bend instead of the arm's segments
  bool has_yaw_ = true;
  bool signed_yaw_ = false;  // the yaw curve is the marker engine's signed yaw
  int last_frame_ = 1;
  double fps_ = 0;
  bool seconds_ = false;
  std::optional<QRectF> zoom_;  // x: frames, y: degrees
  int cursor_frame_ = 0;
};

}  // namespace armmimic::gui
