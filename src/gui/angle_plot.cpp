// The angle plot: the analysis' curves over frames (Qt Charts), its ranges, ticks, layers and
// the cursor. Mouse and wheel interaction: angle_plot_interaction.cpp.
// Length: one chart widget's drawing, each part short, kept together as the chart's state is
// shared.
#include "angle_plot.h"

#include <algorithm>
#include <cmath>

#include <QChart>
#include <QFontMetricsF>
#include <QGraphicsItem>
#include <QGraphicsLayout>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPainter>
#include <QScatterSeries>
#include <QValueAxis>

namespace armmimic::gui {

// One layer of the plot: a path painted in the plot area. Unlike QGraphicsPathItem it never
// works out the outline of its stroke (shape()), which for a curve of thousands of points cost
// the view far more than painting it.
class PlotLayer : public QGraphicsItem {
 public:
  explicit PlotLayer(QGraphicsItem* parent) : QGraphicsItem(parent) {}
  void setPath(const QPainterPath& path) {
    prepareGeometryChange();
    path_ = path;
    bounds_ = path.controlPointRect().adjusted(-3, -3, 3, 3);
  }
  void setPen(const QPen& pen) {
    pen_ = pen;
    update();
  }
  void setBrush(const QBrush& brush) {
    brush_ = brush;
    update();
  }
  const QPainterPath& path() const { return path_; }
  QRectF boundingRect() const override { return bounds_; }
  QPainterPath shape() const override {
    QPainterPath p;
    p.addRect(bounds_);
    return p;
  }
  void paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) override {
    painter->setPen(pen_);
    painter->setBrush(brush_);
    painter->drawPath(path_);
  }

 private:
  QPainterPath path_;
  QRectF bounds_;
  QPen pen_ = Qt::NoPen;
  QBrush brush_ = Qt::NoBrush;
};

namespace {

const QColor kCurveColors[4] = {QColor(0xe0, 0xa0, 0x00), QColor(0x00, 0x9c, 0xd8),
                                QColor(0x8e, 0x5c, 0xc4), QColor(0x2f, 0xa8, 0x3c)};
const QColor kLost(0xd0, 0x3b, 0x2f);

// The smallest of 1, 2, 5 x 10^k (k >= `min_decade`) with about six labels over `span`.
double NiceStep(double span, int min_decade) {
  for (int decade = min_decade;; ++decade) {
    for (double m : {1.0, 2.0, 5.0}) {
      const double step = m * std::pow(10.0, decade);
      if (step * 6 >= span) return step;
    }
  }
}

}  // namespace

AnglePlot::AnglePlot(QWidget* parent)
    : QChartView(parent), lost_(new QScatterSeries), x_(new QValueAxis), y_(new QValueAxis) {
  setObjectName("anglePlot");
  auto* chart = new QChart;
  const QString names[4] = {tr("upper arm"), tr("forearm"), tr("yaw"), tr("bend")};
  for (int c = 0; c < 4; ++c) {
    legend_[c] = new QLineSeries;
    legend_[c]->setName(names[c]);
    chart->addSeries(legend_[c]);
  }
  legend_[int(PlotCurve::kBend)]->setVisible(false);  // shown for marker views
  lost_->setName(tr("lost"));
  chart->addSeries(lost_);
  x_->setTitleText(tr("frame"));
  x_->setLabelFormat("%.0f");
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
  chart->setMargins(QMargins(4, 4, 4, 4));
  chart->layout()->setContentsMargins(0, 0, 0, 0);
  chart->setBackgroundRoundness(0);
  setChart(chart);
  // The layers the series would draw, drawn here so that gaps stay gaps.
  clip_ = new QGraphicsRectItem(chart);
  clip_->setPen(Qt::NoPen);
  clip_->setFlag(QGraphicsItem::ItemClipsChildrenToShape);
  clip_->setZValue(5);  // above the grid, below the legend
  lost_bands_ = new PlotLayer(clip_);
  lost_ticks_ = new PlotLayer(clip_);
  for (PlotLayer*& item : curve_items_) item = new PlotLayer(clip_);
  unsigned_yaw_ = new PlotLayer(clip_);
  cursor_ = new QGraphicsLineItem(clip_);
  connect(chart, &QChart::plotAreaChanged, this, &AnglePlot::fitDegreeTicks);
  connect(chart, &QChart::plotAreaChanged, this, &AnglePlot::redrawLayers);
  setRenderHint(QPainter::Antialiasing);
  setMouseTracking(true);
  setContextMenuPolicy(Qt::PreventContextMenu);  // right button: zoom band or the menu on release
  setMinimumHeight(200);
  applyTheme();
}

void AnglePlot::applyTheme() {
  const QPalette pal = palette();
  const bool dark = pal.color(QPalette::Window).lightness() < 128;
  chart()->setTheme(dark ? QChart::ChartThemeDark : QChart::ChartThemeLight);
  chart()->setBackgroundBrush(pal.color(QPalette::Base));
  // setTheme resets series colours; put ours back.
  for (int c = 0; c < 4; ++c) {
    legend_[c]->setPen(QPen(kCurveColors[c], 1.5));
    curve_items_[c]->setPen(QPen(kCurveColors[c], 1.5, Qt::SolidLine, Qt::RoundCap));
  }
  unsigned_yaw_->setPen(QPen(kCurveColors[int(PlotCurve::kYaw)], 1.2, Qt::DotLine));
  lost_->setColor(kLost);
  lost_->setBorderColor(kLost);
  lost_->setMarkerSize(6);
  lost_bands_->setBrush(QColor(kLost.red(), kLost.green(), kLost.blue(), dark ? 70 : 45));
  lost_ticks_->setBrush(kLost);
  cursor_->setPen(QPen(pal.color(QPalette::WindowText), 1.0, Qt::DashLine));
  x_->setLabelsColor(pal.color(QPalette::WindowText));
  y_->setLabelsColor(pal.color(QPalette::WindowText));
  x_->setTitleBrush(pal.color(QPalette::WindowText));
  y_->setTitleBrush(pal.color(QPalette::WindowText));
  chart()->legend()->setLabelColor(pal.color(QPalette::WindowText));
}

void AnglePlot::setFrameRange(int frame_count, double fps) {
  last_frame_ = std::max(1, frame_count - 1);
  fps_ = std::isfinite(fps) && fps > 0 ? fps : 0;
  if (fps_ <= 0) seconds_ = false;
  zoom_.reset();
  applyRanges();
}

double AnglePlot::xOf(double frame) const { return seconds_ ? frame / fps_ : frame; }
double AnglePlot::frameOf(double x) const { return seconds_ ? x * fps_ : x; }

void AnglePlot::applyRanges() {
  const double first = zoom_ ? zoom_->left() : 0;
  const double last = zoom_ ? zoom_->right() : last_frame_;
  x_->setTitleText(seconds_ ? tr("time (s)") : tr("frame"));
  const double span = xOf(last) - xOf(first);
  const double step = seconds_ ? NiceStep(span, -3) : NiceStep(span, 0);
  // Qt Charts makes an item per tick: the old interval over the new range (a long video opened
  // after a short one, a zoom out) would ask for thousands for a moment. One wide enough for
  // both ranges first.
  x_->setTickInterval(std::max({x_->tickInterval(), x_->max() - x_->min(), span}));
  x_->setRange(xOf(first), xOf(last));
  x_->setTickInterval(step);
  x_->setLabelFormat(
      QString("%.%1f").arg(seconds_ ? std::max(0, int(-std::floor(std::log10(step)))) : 0));
  if (y_->tickType() == QValueAxis::TicksDynamic) {  // as above
    y_->setTickInterval(std::max({y_->tickInterval(), y_->max() - y_->min(), 360.0}));
  }
  y_->setRange(zoom_ ? zoom_->top() : -180, zoom_ ? zoom_->bottom() : 180);
  fitDegreeTicks(chart()->plotArea());
  redrawLayers();
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
  if (!zoom_) {
    y_->setTickType(QValueAxis::TicksFixed);
    y_->setLabelFormat("%.0f");
    if (ticks != y_->tickCount()) y_->setTickCount(ticks);
    return;
  }
  // Zoomed: labels on round degrees, no more of them than fit.
  const double span = zoom_->height();
  double step = 180;
  for (double s : {0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 15.0, 30.0, 45.0, 90.0, 180.0}) {
    if (span / s <= ticks - 1) {
      step = s;
      break;
    }
  }
  y_->setTickInterval(step);
  y_->setTickAnchor(0);
  y_->setTickType(QValueAxis::TicksDynamic);
  y_->setLabelFormat(step < 1 ? "%.1f" : "%.0f");
}

void AnglePlot::setResults(const ResultStore& results, int arm) {
  rows_.clear();
  rows_.reserve(results.all().size());
  file_column_ = false;
  has_yaw_ = false;
  for (const auto& [frame, both] : results.all()) {
    const ArmMeasurement& m = both.Arm(static_cast<std::size_t>(arm));
    if (!m.row()) continue;
    rows_.push_back(m.ToRow());
    // The marker engine (it names each view's image) measures the joint's bend, not segments.
    file_column_ = file_column_ || !m.file.empty();
    has_yaw_ = has_yaw_ || (m.phase == MeasurementPhase::kOk && std::isfinite(m.yaw_deg));
  }
  legend_[int(PlotCurve::kUpper)]->setVisible(!file_column_);
  legend_[int(PlotCurve::kFore)]->setVisible(!file_column_);
  legend_[int(PlotCurve::kBend)]->setVisible(file_column_);
  // The marker engine's yaw has a sign; the plot shows it, so turns either way stay apart.
  const bool signed_yaw = std::any_of(rows_.begin(), rows_.end(), [](const AngleRow& r) {
    return r.ok() && std::isfinite(r.yaw_signed_deg);
  });
  signed_yaw_ = signed_yaw;
  const bool unknown =
      std::any_of(rows_.begin(), rows_.end(), [this](const AngleRow& r) { return signUnknown(r); });
  legend_[int(PlotCurve::kYaw)]->setName(!signed_yaw ? tr("yaw")
                                         : unknown   ? tr("yaw (signed; dotted +-: sign unknown)")
                                                     : tr("yaw (signed)"));
  // An engine that measures no yaw (LK) gets no yaw entry in the legend; no results yet, all.
  legend_[int(PlotCurve::kYaw)]->setVisible(has_yaw_ || rows_.empty());
  redrawLayers();
}

bool AnglePlot::curveShown(PlotCurve c) const { return legend_[int(c)]->isVisible(); }

double AnglePlot::valueOf(const AngleRow& row, PlotCurve c) const {
  if (!row.ok() || !curveShown(c)) return std::nan("");
  switch (c) {
    case PlotCurve::kUpper:
      return row.upper_deg;
    case PlotCurve::kFore:
      return row.fore_deg;
    case PlotCurve::kYaw:  // a signed curve leaves a gap where the sign is unknown
      return std::isfinite(row.yaw_signed_deg) ? row.yaw_signed_deg
             : signed_yaw_                     ? std::nan("")
                                               : row.yaw_deg;
    case PlotCurve::kBend:
      return row.bend_deg;
  }
  return std::nan("");
}

std::vector<std::pair<int, int>> AnglePlot::runs(PlotCurve c) const {
  std::vector<std::pair<int, int>> out;
  for (const AngleRow& row : rows_) {
    if (!std::isfinite(valueOf(row, c))) continue;
    if (!out.empty() && out.back().second == row.frame - 1) {
      out.back().second = row.frame;
    } else {
      out.emplace_back(row.frame, row.frame);
    }
  }
  return out;
}

QPointF AnglePlot::toChart(double frame, double deg) const {
  const QRectF area = chart()->plotArea();
  const double x0 = x_->min(), x1 = x_->max(), y0 = y_->min(), y1 = y_->max();
  return QPointF(area.left() + (xOf(frame) - x0) / (x1 - x0) * area.width(),
                 area.bottom() - (deg - y0) / (y1 - y0) * area.height());
}

namespace {

// Adds one run of consecutive frames (screen points, left to right) to `path`. A lone frame is
// a dot. Where a run has more points than pixel columns, each column keeps its first, lowest,
// highest and last point (the M4 reduction): the line drawn is the same, the path far shorter.
void AddRun(const QPolygonF& run, QPainterPath* path) {
  if (run.size() == 1) {
    path->addEllipse(run.front(), 2.0, 2.0);
    return;
  }
  if (run.size() <= 4 * (run.back().x() - run.front().x() + 1)) {
    path->addPolygon(run);
    return;
  }
  QPolygonF reduced;
  for (int i = 0; i < run.size();) {
    const double column = std::floor(run[i].x());
    int j = i, low = i, high = i;
    for (; j < run.size() && std::floor(run[j].x()) == column; ++j) {
      if (run[j].y() < run[low].y()) low = j;
      if (run[j].y() > run[high].y()) high = j;
    }
    reduced << run[i] << run[std::min(low, high)] << run[std::max(low, high)] << run[j - 1];
    i = j;
  }
  path->addPolygon(reduced);
}

}  // namespace

void AnglePlot::redrawLayers() {
  const QRectF area = chart()->plotArea();
  clip_->setRect(area);
  // Only the frames in view (and one beyond each side, so lines run to the edge).
  const double first = std::floor(frameOf(x_->min())) - 1;
  const double last = std::ceil(frameOf(x_->max())) + 1;
  // More frames than pixels: one-pixel lines, which Qt's raster engine draws on a far faster
  // path than wider ones (bench/gui/plot_bench.cpp), and which look as thick there.
  const double width = (last - first) > area.width() ? 1.0 : 1.5;
  for (int c = 0; c < 4; ++c) {
    curve_items_[c]->setPen(QPen(kCurveColors[c], width, Qt::SolidLine, Qt::RoundCap));
    QPainterPath path;
    QPolygonF run;  // consecutive measured frames
    int previous = -2;
    double previous_v = 0;
    for (const AngleRow& row : rows_) {
      if (row.frame < first || row.frame > last) continue;
      const double v = valueOf(row, PlotCurve(c));
      if (!std::isfinite(v) || row.frame != previous + 1) {  // a gap ends the line
        if (!run.isEmpty()) AddRun(run, &path);
        run.clear();
      }
      if (!std::isfinite(v)) continue;
      if (!run.isEmpty() && std::abs(v - previous_v) > 180) {
        // A direction crossing ±180° between two frames turned the short way: the line leaves
        // at one edge and comes back at the other, instead of a wall across the plot.
        const double step = v - previous_v + (v < previous_v ? 360 : -360);
        const double edge = step > 0 ? 180 : -180;
        const double at = previous + (edge - previous_v) / step;
        run << toChart(at, edge);
        AddRun(run, &path);
        run.clear();
        run << toChart(at, -edge);
      }
      run << toChart(row.frame, v);
      previous = row.frame;
      previous_v = v;
    }
    if (!run.isEmpty()) AddRun(run, &path);
    curve_items_[c]->setPath(path);
  }
  // Each run of lost frames is a red band, with a mark on the bottom edge.
  QPainterPath bands, ticks;
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    if (rows_[i].ok() || rows_[i].frame < first || rows_[i].frame > last) continue;
    std::size_t j = i;
    while (j + 1 < rows_.size() && !rows_[j + 1].ok() && rows_[j + 1].frame == rows_[j].frame + 1) {
      ++j;
    }
    const double left = toChart(rows_[i].frame - 0.5, 0).x();
    const double right = toChart(rows_[j].frame + 0.5, 0).x();
    const double w = std::max(1.0, right - left);
    bands.addRect(QRectF(left, area.top(), w, area.height()));
    ticks.addRect(QRectF(left + w / 2 - std::max(2.0, w / 2 - 1), area.bottom() - 8,
                         std::max(4.0, w - 2), 8));
    i = j;
  }
  lost_bands_->setPath(bands);
  lost_ticks_->setPath(ticks);
  // A yaw whose sign is unknown: hollow marks at +|yaw| and -|yaw|, joined by a dotted line.
  QPainterPath unsigned_marks;
  for (const QPointF& p : unsignedYawPoints()) {
    if (p.x() < first || p.x() > last || !curveShown(PlotCurve::kYaw)) continue;
    const QPointF up = toChart(p.x(), p.y()), down = toChart(p.x(), -p.y());
    unsigned_marks.addEllipse(up, 3.0, 3.0);
    unsigned_marks.addEllipse(down, 3.0, 3.0);
    unsigned_marks.moveTo(up);
    unsigned_marks.lineTo(down);
  }
  unsigned_yaw_->setPath(unsigned_marks);
  const double cx = toChart(cursor_frame_, 0).x();
  cursor_->setLine(cx, area.top(), cx, area.bottom());
}

void AnglePlot::setCursorFrame(int frame) {
  cursor_frame_ = frame;
  const QRectF area = chart()->plotArea();
  const double cx = toChart(frame, 0).x();
  cursor_->setLine(cx, area.top(), cx, area.bottom());
}

double AnglePlot::largestStepDeg(PlotCurve curve) const {
  const QPainterPath& path = curve_items_[int(curve)]->path();
  const QRectF area = chart()->plotArea();
  const double per_px = (y_->max() - y_->min()) / area.height();
  double largest = 0;
  for (int i = 1; i < path.elementCount(); ++i) {
    if (!path.elementAt(i).isLineTo()) continue;
    largest = std::max(largest, std::abs(path.elementAt(i).y - path.elementAt(i - 1).y) * per_px);
  }
  return largest;
}

int AnglePlot::pointCount() const {
  int n = 0;
  for (const auto& [first, last] : runs(PlotCurve::kUpper)) n += last - first + 1;
  return n;
}

int AnglePlot::lostCount() const {
  return int(std::count_if(rows_.begin(), rows_.end(), [](const AngleRow& r) { return !r.ok(); }));
}

int AnglePlot::bendCount() const {
  int n = 0;
  for (const auto& [first, last] : runs(PlotCurve::kBend)) n += last - first + 1;
  return n;
}

bool AnglePlot::yawShown() const { return curveShown(PlotCurve::kYaw); }

QPointF AnglePlot::valueAt(const QPointF& widget_pos) const {
  const QPointF chart_pos = chart()->mapFromScene(mapToScene(widget_pos.toPoint()));
  const QRectF area = chart()->plotArea();
  const double x =
      x_->min() + (chart_pos.x() - area.left()) / area.width() * (x_->max() - x_->min());
  const double y =
      y_->min() + (area.bottom() - chart_pos.y()) / area.height() * (y_->max() - y_->min());
  return QPointF(frameOf(x), y);
}

QList<QPointF> AnglePlot::yawPoints() const {
  QList<QPointF> out;
  for (const AngleRow& row : rows_) {
    const double v = valueOf(row, PlotCurve::kYaw);
    if (std::isfinite(v)) out.append(QPointF(row.frame, v));
  }
  return out;
}

bool AnglePlot::signUnknown(const AngleRow& row) const {
  return signed_yaw_ && row.ok() && std::isnan(row.yaw_signed_deg) && std::isfinite(row.yaw_deg);
}

QList<QPointF> AnglePlot::unsignedYawPoints() const {
  QList<QPointF> out;
  for (const AngleRow& row : rows_) {
    if (signUnknown(row)) out.append(QPointF(row.frame, row.yaw_deg));
  }
  return out;
}

int AnglePlot::frameAt(const QPointF& widget_pos) const {
  const double frame = valueAt(widget_pos).x();
  return static_cast<int>(std::lround(std::clamp(frame, frameOf(x_->min()), frameOf(x_->max()))));
}

void AnglePlot::changeEvent(QEvent* event) {
  QChartView::changeEvent(event);
  if (event->type() == QEvent::PaletteChange) applyTheme();
}

}  // namespace armmimic::gui
