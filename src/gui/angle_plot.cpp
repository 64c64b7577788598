#include "angle_plot.h"

#include <cmath>

#include <QChart>
#include <QFontMetricsF>
#include <QGraphicsLayout>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QMouseEvent>
#include <QScatterSeries>
#include <QValueAxis>

namespace armmimic::gui {

AnglePlot::AnglePlot(QWidget* parent)
    : QChartView(parent),
      upper_(new QLineSeries),
      fore_(new QLineSeries),
      yaw_(new QLineSeries),
      bend_(new QLineSeries),
      lost_(new QScatterSeries),
      cursor_(new QLineSeries),
      x_(new QValueAxis),
      y_(new QValueAxis) {
  setObjectName("anglePlot");
  auto* chart = new QChart;
  upper_->setName(tr("upper arm"));
  fore_->setName(tr("forearm"));
  yaw_->setName(tr("yaw"));
  bend_->setName(tr("bend"));
  bend_->setVisible(false);  // shown for marker views
  lost_->setName(tr("lost"));
  lost_->setMarkerSize(6);
  lost_->setColor(QColor(0xd0, 0x3b, 0x2f));
  lost_->setBorderColor(QColor(0xd0, 0x3b, 0x2f));
  upper_->setPen(QPen(QColor(0xe0, 0xa0, 0x00), 1.5));
  fore_->setPen(QPen(QColor(0x00, 0x9c, 0xd8), 1.5));
  yaw_->setPen(QPen(QColor(0x8e, 0x5c, 0xc4), 1.5));
  cursor_->setPen(QPen(QColor(0x80, 0x80, 0x80), 1.0, Qt::DashLine));
  for (QAbstractSeries* s :
       {static_cast<QAbstractSeries*>(upper_), static_cast<QAbstractSeries*>(fore_),
        static_cast<QAbstractSeries*>(yaw_), static_cast<QAbstractSeries*>(bend_),
        static_cast<QAbstractSeries*>(lost_), static_cast<QAbstractSeries*>(cursor_)}) {
    chart->addSeries(s);
  }
  x_->setTitleText(tr("frame"));
  x_->setLabelFormat("%d");
  x_->setTickType(QValueAxis::TicksDynamic);
  x_->setTickAnchor(0);
  x_->setRange(0, 1);
  x_->setTickInterval(1);
  y_->setTitleText(tr("degrees"));
  y_->setRange(-180, 180);
  y_->setLabelFormat("%.0f");
  y_->setTickCount(9);
  chart->addAxis(x_, Qt::AlignBottom);
  chart->addAxis(y_, Qt::AlignLeft);
  for (QAbstractSeries* s : chart->series()) {
    s->attachAxis(x_);
    s->attachAxis(y_);
  }
  chart->legend()->setAlignment(Qt::AlignTop);
  chart->legend()->markers(cursor_).first()->setVisible(false);
  chart->setMargins(QMargins(4, 4, 4, 4));
  chart->layout()->setContentsMargins(0, 0, 0, 0);
  chart->setBackgroundRoundness(0);
  setChart(chart);
  connect(chart, &QChart::plotAreaChanged, this, &AnglePlot::fitDegreeTicks);
  setRenderHint(QPainter::Antialiasing);
  setMinimumHeight(200);
  applyTheme();
  setCursorFrame(0);
}

void AnglePlot::applyTheme() {
  const QPalette pal = palette();
  const bool dark = pal.color(QPalette::Window).lightness() < 128;
  chart()->setTheme(dark ? QChart::ChartThemeDark : QChart::ChartThemeLight);
  chart()->setBackgroundBrush(pal.color(QPalette::Base));
  // setTheme resets series colours; put ours back.
  upper_->setPen(QPen(QColor(0xe0, 0xa0, 0x00), 1.5));
  fore_->setPen(QPen(QColor(0x00, 0x9c, 0xd8), 1.5));
  yaw_->setPen(QPen(QColor(0x8e, 0x5c, 0xc4), 1.5));
  bend_->setPen(QPen(QColor(0x2f, 0xa8, 0x3c), 1.5));
  lost_->setColor(QColor(0xd0, 0x3b, 0x2f));
  lost_->setBorderColor(QColor(0xd0, 0x3b, 0x2f));
  lost_->setMarkerSize(6);
  cursor_->setPen(QPen(pal.color(QPalette::WindowText), 1.0, Qt::DashLine));
  x_->setLabelsColor(pal.color(QPalette::WindowText));
  y_->setLabelsColor(pal.color(QPalette::WindowText));
  x_->setTitleBrush(pal.color(QPalette::WindowText));
  y_->setTitleBrush(pal.color(QPalette::WindowText));
  chart()->legend()->setLabelColor(pal.color(QPalette::WindowText));
}

void AnglePlot::setFrameRange(int frame_count) {
  const int last = std::max(1, frame_count - 1);
  x_->setRange(0, last);
  // About six labels, each on a whole frame: 1, 2, 5, 10, 20, 50, ...
  double step = 1;
  for (double decade = 1; step * 6 < last; decade *= 10) {
    for (double m : {1.0, 2.0, 5.0}) {
      step = m * decade;
      if (step * 6 >= last) break;
    }
  }
  x_->setTickInterval(step);
}

double AnglePlot::frameTickStep() const { return x_->tickInterval(); }

int AnglePlot::degreeTickCount() const { return y_->tickCount(); }

void AnglePlot::fitDegreeTicks(const QRectF& plot_area) {
  // Qt Charts cuts a label to "..." when it is taller than the gap between two ticks (the
  // Angles dock's default height gave 9 labels 11 px apart).
  const double label_px = QFontMetricsF(y_->labelsFont()).height() * 1.3;
  int ticks = 3;             // -180, 0, 180
  for (int n : {9, 7, 5}) {  // every 45, 60 or 90 degrees
    if (plot_area.height() / (n - 1) >= label_px) {
      ticks = n;
      break;
    }
  }
  if (ticks != y_->tickCount()) y_->setTickCount(ticks);
}

void AnglePlot::setResults(const ResultStore& results) {
  QList<QPointF> upper, fore, yaw, bend, lost;
  int signed_yaw = 0;
  for (const auto& [frame, m] : results.all()) {
    if (m.phase == MeasurementPhase::kLost) {
      lost.append(QPointF(frame, -175));
      continue;
    }
    if (m.phase != MeasurementPhase::kOk) continue;
    if (std::isfinite(m.upper_deg)) upper.append(QPointF(frame, m.upper_deg));
    if (std::isfinite(m.fore_deg)) fore.append(QPointF(frame, m.fore_deg));
    // The marker engine's yaw has a sign; the plot shows it, so turns either way stay apart.
    if (std::isfinite(m.yaw_signed_deg)) {
      yaw.append(QPointF(frame, m.yaw_signed_deg));
      ++signed_yaw;
    } else if (std::isfinite(m.yaw_deg)) {
      yaw.append(QPointF(frame, m.yaw_deg));
    }
    // The marker engine (it names each view's image) measures the joint's bend, not segments.
    if (!m.file.empty() && std::isfinite(m.bend_deg)) bend.append(QPointF(frame, m.bend_deg));
  }
  upper_->replace(upper);
  fore_->replace(fore);
  yaw_->replace(yaw);
  yaw_->setName(signed_yaw > 0 ? tr("yaw (signed)") : tr("yaw"));
  bend_->replace(bend);
  const bool marker = !bend.isEmpty();
  upper_->setVisible(!marker);
  fore_->setVisible(!marker);
  bend_->setVisible(marker);
  // An engine that measures no yaw (LK) gets no yaw entry in the legend; no results yet, all.
  yaw_->setVisible(!yaw.isEmpty() || results.size() == 0);
  lost_->replace(lost);
}

void AnglePlot::setCursorFrame(int frame) {
  cursor_frame_ = frame;
  cursor_->replace(QList<QPointF>{QPointF(frame, -180), QPointF(frame, 180)});
}

int AnglePlot::pointCount() const { return static_cast<int>(upper_->count()); }
int AnglePlot::lostCount() const { return static_cast<int>(lost_->count()); }
int AnglePlot::bendCount() const { return static_cast<int>(bend_->count()); }
bool AnglePlot::yawShown() const { return yaw_->isVisible(); }
QList<QPointF> AnglePlot::yawPoints() const { return yaw_->points(); }

int AnglePlot::frameAt(const QPointF& widget_pos) const {
  const QPointF scene = mapToScene(widget_pos.toPoint());
  const QPointF value = chart()->mapToValue(chart()->mapFromScene(scene), upper_);
  return static_cast<int>(std::lround(std::clamp(value.x(), x_->min(), x_->max())));
}

void AnglePlot::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton && chart()->plotArea().contains(event->position())) {
    emit frameClicked(frameAt(event->position()));
  }
  QChartView::mousePressEvent(event);
}

void AnglePlot::changeEvent(QEvent* event) {
  QChartView::changeEvent(event);
  if (event->type() == QEvent::PaletteChange) applyTheme();
}

void AnglePlot::mouseMoveEvent(QMouseEvent* event) {
  if ((event->buttons() & Qt::LeftButton) && chart()->plotArea().contains(event->position())) {
    emit frameClicked(frameAt(event->position()));
  }
  QChartView::mouseMoveEvent(event);
}

}  // namespace armmimic::gui
