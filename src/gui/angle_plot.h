// AnglePlot: upper arm, forearm and yaw against the frame (Qt Charts); for the marker engine's
// views, yaw and bend. Lost frames show as red marks along the bottom, the video cursor as a
// vertical line; a click seeks to that frame.
#pragma once

#include <QChartView>

#include "result_store.h"

class QLineSeries;
class QScatterSeries;
class QValueAxis;

namespace armmimic::gui {

class AnglePlot : public QChartView {
  Q_OBJECT
 public:
  explicit AnglePlot(QWidget* parent = nullptr);

  void setFrameRange(int frame_count);
  // Rebuilds the series from `results` (called on the window's throttle timer).
  void setResults(const ResultStore& results);
  void setCursorFrame(int frame);
  int cursorFrame() const { return cursor_frame_; }
  int pointCount() const;  // points on the angle series, for tests
  int lostCount() const;
  int bendCount() const;             // points on the bend series (marker views)
  bool yawShown() const;             // the yaw series and its legend entry
  QList<QPointF> yawPoints() const;  // (frame, yaw): signed for marker views
  // The frame axis' label step: 1, 2, 5, 10, 20, ... so that every label is a whole frame.
  double frameTickStep() const;
  // Labels on the degree axis: every 45° when the plot is tall enough, else every 60°, 90° or
  // 180°, so that no label is cut to "...".
  int degreeTickCount() const;
  // Frame under a widget position (rounded), for clicks.
  int frameAt(const QPointF& widget_pos) const;

 signals:
  void frameClicked(int frame);

 protected:
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  // A switch between the dark and the light scheme while running repaints the chart in it.
  void changeEvent(QEvent* event) override;

 private:
  void applyTheme();
  void fitDegreeTicks(const QRectF& plot_area);
  QLineSeries* upper_;
  QLineSeries* fore_;
  QLineSeries* yaw_;
  QLineSeries* bend_;
  QScatterSeries* lost_;
  QLineSeries* cursor_;
  QValueAxis* x_;
  QValueAxis* y_;
  int cursor_frame_ = 0;
};

}  // namespace armmimic::gui
