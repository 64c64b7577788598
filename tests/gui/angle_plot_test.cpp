// The angle plot as the operator reads it: the degree labels stay readable at any height of the
// Angles dock.
#include <algorithm>

#include <QChart>
#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QImage>
#include <QPalette>
#include <QStringList>
#include <QTest>

#include "angle_plot.h"
#include "armmimic/core/angle_file.h"
#include "gui_fixture.h"
#include "overlay.h"
#include "result_store.h"

namespace armmimic::test {
namespace {

using gui::AnglePlot;

class AnglePlotTest : public GuiTest {
 protected:
  // Every text the chart draws (axis labels and titles, legend).
  static QStringList Texts(const AnglePlot& plot) {
    QStringList out;
    for (QGraphicsItem* item : plot.scene()->items()) {
      if (auto* text = dynamic_cast<QGraphicsTextItem*>(item); text && text->isVisible()) {
        out << text->toPlainText();
      }
    }
    return out;
  }
  static bool AnyCut(const QStringList& texts) {
    for (const QString& t : texts) {
      if (t.contains("...") || t.contains(QChar(0x2026))) return true;
    }
    return false;
  }
};

TEST_F(AnglePlotTest, DegreeLabelsAreNeverCutWhateverTheHeight) {
  AnglePlot plot;
  plot.setFrameRange(255);
  plot.resize(900, 200);  // the Angles dock's height on a first start
  plot.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&plot));
  ASSERT_TRUE(WaitUntil([&] { return plot.degreeTickCount() < 9; }, 5000));
  QTest::qWait(50);
  QStringList texts = Texts(plot);
  EXPECT_TRUE(texts.contains("180")) << texts.join('|').toStdString();
  EXPECT_TRUE(texts.contains("-180")) << texts.join('|').toStdString();
  EXPECT_FALSE(AnyCut(texts)) << texts.join('|').toStdString();

  // Taller: a label every 45 degrees, still whole.
  plot.resize(900, 600);
  ASSERT_TRUE(WaitUntil([&] { return plot.degreeTickCount() == 9; }, 5000));
  QTest::qWait(50);
  texts = Texts(plot);
  EXPECT_TRUE(texts.contains("135")) << texts.join('|').toStdString();
  EXPECT_FALSE(AnyCut(texts)) << texts.join('|').toStdString();
}

TEST_F(AnglePlotTest, FollowsASchemeSwitchWhileRunning) {
  AnglePlot plot;
  plot.resize(600, 300);
  plot.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&plot));
  QPalette dark = plot.palette();
  dark.setColor(QPalette::Window, QColor(0x30, 0x30, 0x30));
  dark.setColor(QPalette::Base, QColor(0x20, 0x20, 0x20));
  dark.setColor(QPalette::WindowText, QColor(0xee, 0xee, 0xee));
  dark.setColor(QPalette::Text, QColor(0xee, 0xee, 0xee));
  plot.setPalette(dark);  // what a switch of the desktop's scheme delivers
  EXPECT_EQ(plot.chart()->backgroundBrush().color(), QColor(0x20, 0x20, 0x20));
  const QImage shot = plot.grab().toImage();
  EXPECT_LT(QColor(shot.pixel(shot.width() / 2, shot.height() / 2)).lightness(), 80);
}

// Rows of an arm engine: `yaw` as given (nan for the LK engine, which measures none).
gui::ResultStore ArmRows(double yaw) {
  gui::ResultStore store;
  for (int f = 0; f < 20; ++f) {
    ArmMeasurement m;
    m.frame = f;
    m.phase = MeasurementPhase::kOk;
    m.upper_deg = -90 + f;
    m.fore_deg = -80 + f;
    m.yaw_deg = yaw;
    store.add(m);
  }
  return store;
}

TEST_F(AnglePlotTest, YawIsListedOnlyForEnginesThatMeasureIt) {
  AnglePlot plot;
  plot.setFrameRange(20);
  plot.resize(600, 300);
  plot.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&plot));
  EXPECT_TRUE(plot.yawShown());  // nothing analysed yet: the legend lists every angle
  plot.setResults(ArmRows(kNaN));
  EXPECT_EQ(plot.pointCount(), 20);
  EXPECT_FALSE(plot.yawShown());
  EXPECT_FALSE(Texts(plot).contains("yaw"));
  plot.setResults(ArmRows(12));
  EXPECT_TRUE(plot.yawShown());
}

// 21 frames at 30 fps, upper arm 30°, forearm 60°, frames 10, 17 and 19 lost (18 alone between
// two lost ones) and yaw measured only on frames 0..4 (a straight arm) and 15..20.
gui::ResultStore RowsWithALostFrame() {
  gui::ResultStore store;
  for (int f = 0; f <= 20; ++f) {
    ArmMeasurement m;
    m.frame = f;
    m.time_s = f / 30.0;
    m.phase = (f == 10 || f == 17 || f == 19) ? MeasurementPhase::kLost : MeasurementPhase::kOk;
    m.upper_deg = 30;
    m.fore_deg = 60;
    m.yaw_deg = (f < 5 || f >= 15) ? 20 : kNaN;
    store.add(m);
  }
  return store;
}

class PlotOnScreen : public AnglePlotTest {
 protected:
  void SetUp() override {
    AnglePlotTest::SetUp();
    plot_.setFrameRange(21, 30);
    plot_.resize(800, 400);
    plot_.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&plot_));
    plot_.setResults(RowsWithALostFrame());
    QTest::qWait(20);
  }
  // The widget position of (frame, degrees).
  QPoint At(double frame, double deg) const {
    const QPointF value(plot_.timeAxis() ? frame / 30.0 : frame, deg);
    return plot_.mapFromScene(plot_.chart()->mapToScene(plot_.chart()->mapToPosition(value)));
  }
  AnglePlot plot_;
};

TEST_F(PlotOnScreen, ALostFrameLeavesAGap) {
  EXPECT_EQ(plot_.runs(gui::PlotCurve::kUpper),
            (std::vector<std::pair<int, int>>{{0, 9}, {11, 16}, {18, 18}, {20, 20}}));
  EXPECT_EQ(plot_.runs(gui::PlotCurve::kYaw),
            (std::vector<std::pair<int, int>>{{0, 4}, {15, 16}, {18, 18}, {20, 20}}));
  EXPECT_EQ(plot_.lostCount(), 3);
  EXPECT_EQ(plot_.pointCount(), 18);
  // On screen: the upper-arm line crosses frame 5 at 30 degrees and does not cross frame 10.
  const QImage shot = plot_.grab().toImage();
  auto line_near = [&](double frame) {
    const QPoint p = At(frame, 30);
    for (int dy = -2; dy <= 2; ++dy) {
      const QColor c = shot.pixelColor(p.x(), p.y() + dy);
      if (c.red() > 180 && c.green() > 120 && c.green() < 190 && c.blue() < 60) return true;
    }
    return false;
  };
  EXPECT_TRUE(line_near(5));
  EXPECT_TRUE(line_near(15));
  EXPECT_TRUE(line_near(18));  // a lone measured frame still shows, as a dot
  EXPECT_FALSE(line_near(17.4));
  EXPECT_FALSE(line_near(10));
  EXPECT_FALSE(line_near(9.5));
  EXPECT_FALSE(line_near(10.5));
  // The lost frame is shaded red from top to bottom.
  const QColor band = shot.pixelColor(At(10, 100));
  EXPECT_GT(band.red(), band.green() + 20);
}

TEST_F(PlotOnScreen, HoveringReadsOutFrameTimeAndValues) {
  QString readout;
  QObject::connect(&plot_, &AnglePlot::hovered, [&](const QString& t) { readout = t; });
  QTest::mouseMove(plot_.viewport(), At(12, 0));
  ASSERT_TRUE(WaitUntil([&] { return !readout.isEmpty(); }, 2000));
  EXPECT_TRUE(readout.startsWith("frame 12 · 0.400 s")) << readout.toStdString();
  EXPECT_TRUE(readout.contains(QString("upper 30.0") + QChar(0x00B0))) << readout.toStdString();
  EXPECT_TRUE(readout.contains(QString("yaw ") + QChar(0x2014))) << readout.toStdString();
  QTest::mouseMove(plot_.viewport(), At(10, 0));
  ASSERT_TRUE(WaitUntil([&] { return readout.startsWith("frame 10"); }, 2000));
  EXPECT_TRUE(readout.endsWith("lost")) << readout.toStdString();
}

TEST_F(PlotOnScreen, DraggingWithTheRightButtonZoomsAndADoubleClickResets) {
  QTest::mousePress(plot_.viewport(), Qt::RightButton, Qt::NoModifier, At(4, 90));
  QTest::mouseMove(plot_.viewport(), At(10, 40));
  QTest::mouseRelease(plot_.viewport(), Qt::RightButton, Qt::NoModifier, At(16, 0));
  ASSERT_TRUE(plot_.isZoomed());
  const auto [first, last] = plot_.visibleFrames();
  EXPECT_NEAR(first, 4, 1);
  EXPECT_NEAR(last, 16, 1);
  const auto [low, high] = plot_.visibleDegrees();
  EXPECT_NEAR(low, 0, 2);
  EXPECT_NEAR(high, 90, 2);
  // A left click still seeks, zoomed or not.
  int clicked = -1;
  QObject::connect(&plot_, &AnglePlot::frameClicked, [&](int f) { clicked = f; });
  QTest::mouseClick(plot_.viewport(), Qt::LeftButton, Qt::NoModifier, At(8, 45));
  EXPECT_EQ(clicked, 8);
  QTest::mouseDClick(plot_.viewport(), Qt::LeftButton, Qt::NoModifier, At(8, 45));
  EXPECT_FALSE(plot_.isZoomed());
  EXPECT_EQ(plot_.visibleFrames(), std::make_pair(0, 20));
  EXPECT_EQ(plot_.visibleDegrees(), std::make_pair(-180.0, 180.0));
}

TEST_F(PlotOnScreen, TheAxisShowsFramesOrSeconds) {
  EXPECT_TRUE(plot_.canShowTime());
  plot_.setTimeAxis(true);
  EXPECT_TRUE(Texts(plot_).contains("time (s)"));
  EXPECT_DOUBLE_EQ(plot_.frameTickStep(), 0.2);  // 0.667 s in about six labels
  EXPECT_EQ(plot_.visibleFrames(), std::make_pair(0, 20));
  int clicked = -1;
  QObject::connect(&plot_, &AnglePlot::frameClicked, [&](int f) { clicked = f; });
  QTest::mouseClick(plot_.viewport(), Qt::LeftButton, Qt::NoModifier, At(15, 0));
  EXPECT_EQ(clicked, 15);  // clicks still seek to frames
  plot_.setTimeAxis(false);
  EXPECT_TRUE(Texts(plot_).contains("frame"));
  // Still images have no time axis.
  plot_.setFrameRange(21, 0);
  EXPECT_FALSE(plot_.canShowTime());
  plot_.setTimeAxis(true);
  EXPECT_FALSE(plot_.timeAxis());
}

TEST_F(PlotOnScreen, SavesItselfAsPngAndSvgAndItsRangeAsRows) {
  const QString png = QString::fromStdString(tmp_.file("plot.png"));
  const QString svg = QString::fromStdString(tmp_.file("plot.svg"));
  ASSERT_EQ(plot_.saveImage(png), QString());
  ASSERT_EQ(plot_.saveImage(svg), QString());
  const QImage image(png);
  EXPECT_EQ(image.size(), plot_.viewport()->size() * 2);
  const std::string text = ReadFile(svg.toStdString());
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("upper arm"), std::string::npos);  // the legend, as text
  EXPECT_NE(plot_.saveImage("/nonexistent-folder/plot.png").indexOf("/nonexistent-folder"), -1);
  plot_.zoomTo(8, 12, -180, 180);
  const std::vector<AngleRow> rows = plot_.visibleRows();
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows.front().frame, 8);
  EXPECT_FALSE(rows[2].ok());  // frame 10, lost, is a row of its own
}

// The forearm of a real clip between frames 25 and 26: -178.25° then 178.15°, a turn of about
// 4° across the ±180° seam, which must not be drawn as a line across the whole plot.
TEST_F(PlotOnScreen, ACurveCrossingTheSeamIsBrokenThereAndReadsItsTrueValue) {
  gui::ResultStore store;
  const double fore[] = {-170, -174, -178.25, 178.15, 175, 171};
  for (int i = 0; i < 6; ++i) {
    ArmMeasurement m;
    m.frame = 23 + i;
    m.time_s = m.frame / 30.0;
    m.phase = MeasurementPhase::kOk;
    m.upper_deg = -90 + i;
    m.fore_deg = fore[i];
    store.add(m);
  }
  plot_.setFrameRange(30, 30);
  plot_.setResults(store);
  QTest::qWait(20);
  EXPECT_LE(plot_.largestStepDeg(gui::PlotCurve::kFore), 180.0);
  EXPECT_LT(plot_.largestStepDeg(gui::PlotCurve::kFore), 10.0);  // the 4° turn, in two halves
  EXPECT_LT(plot_.largestStepDeg(gui::PlotCurve::kUpper), 2.0);
  // Both halves are drawn: near -180° before the seam, near +180° after it.
  const QImage shot = plot_.grab().toImage();
  auto drawn_near = [&](double frame, double deg) {
    const QPoint p = At(frame, deg);
    for (int dy = -3; dy <= 3; ++dy) {
      const QColor c = shot.pixelColor(p.x(), std::clamp(p.y() + dy, 0, shot.height() - 1));
      if (c.blue() > 150 && c.red() < 80) return true;  // the forearm's blue
    }
    return false;
  };
  EXPECT_TRUE(drawn_near(24.5, -176)) << "before the seam";
  EXPECT_TRUE(drawn_near(26.5, 176.5)) << "after the seam";
  EXPECT_FALSE(drawn_near(25.5, 0)) << "no wall across the plot";
  // Hovering reads the values as measured, not unwrapped.
  QString readout;
  QObject::connect(&plot_, &AnglePlot::hovered, [&](const QString& t) { readout = t; });
  QTest::mouseMove(plot_.viewport(), At(24, 0));  // a move, wherever the pointer was before
  ASSERT_TRUE(WaitUntil([&] { return readout.startsWith("frame 24"); }, 2000));
  QTest::mouseMove(plot_.viewport(), At(26, 0));
  ASSERT_TRUE(WaitUntil([&] { return readout.startsWith("frame 26"); }, 2000));
  EXPECT_TRUE(readout.contains(QString("fore 178.2") + QChar(0x00B0)) ||
              readout.contains(QString("fore 178.1") + QChar(0x00B0)))
      << readout.toStdString();
}

// Marker views (each names its image) with a signed yaw, except view 4 whose sign the engine
// could not tell: it has a yaw of 12 degrees and no signed yaw.
gui::ResultStore MarkerRowsWithAnUnknownSign() {
  gui::ResultStore store;
  for (int f = 0; f < 10; ++f) {
    ArmMeasurement m;
    m.frame = f;
    m.file = "view_00" + std::to_string(f) + ".png";
    m.phase = MeasurementPhase::kOk;
    m.yaw_signed_deg = f == 4 ? kNaN : -30 + 5 * f;
    m.yaw_deg = f == 4 ? 12 : std::abs(m.yaw_signed_deg);
    m.bend_deg = 10;
    store.add(m);
  }
  return store;
}

TEST_F(AnglePlotTest, AYawWhoseSignIsUnknownIsMarkedNotDrawnAsPositive) {
  AnglePlot plot;
  plot.setFrameRange(10);
  plot.resize(800, 400);
  plot.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&plot));
  const gui::ResultStore rows = MarkerRowsWithAnUnknownSign();
  plot.setResults(rows);
  QTest::qWait(20);
  // The signed curve leaves a gap at view 4; the view is listed apart with its magnitude.
  EXPECT_EQ(plot.runs(gui::PlotCurve::kYaw), (std::vector<std::pair<int, int>>{{0, 3}, {5, 9}}));
  EXPECT_EQ(plot.unsignedYawPoints(), (QList<QPointF>{QPointF(4, 12)}));
  for (const QPointF& p : plot.yawPoints()) EXPECT_NE(p.x(), 4);
  const QStringList texts = Texts(plot);
  EXPECT_TRUE(texts.filter("sign unknown").size() == 1) << texts.join('|').toStdString();
  // On screen: the yaw's colour at +12 and at -12 degrees over view 4, where no curve runs.
  auto at = [&](double frame, double deg) {
    return plot.mapFromScene(plot.chart()->mapToScene(plot.chart()->mapToPosition({frame, deg})));
  };
  const QImage shot = plot.grab().toImage();
  auto purple_near = [&](QPoint p) {
    for (int dy = -4; dy <= 4; ++dy) {
      for (int dx = -4; dx <= 4; ++dx) {
        const QColor c = shot.pixelColor(p.x() + dx, p.y() + dy);
        if (c.blue() > 150 && c.red() > 100 && c.green() < 130) return true;
      }
    }
    return false;
  };
  EXPECT_TRUE(purple_near(at(4, 12)));
  EXPECT_TRUE(purple_near(at(4, -12)));
  EXPECT_FALSE(purple_near(at(4, 60)));
  // Hovering over view 4 says the sign is unknown.
  QString readout;
  QObject::connect(&plot, &AnglePlot::hovered, [&](const QString& t) { readout = t; });
  QTest::mouseMove(plot.viewport(), at(4, 0));
  ASSERT_TRUE(WaitUntil([&] { return readout.startsWith("frame 4"); }, 2000));
  EXPECT_TRUE(readout.contains("(sign unknown)")) << readout.toStdString();
  // So does the image's overlay; a view with a sign shows it.
  EXPECT_EQ(gui::MakeOverlayTexts(rows.find(4), 4, 10).yaw,
            QString("yaw +-12.0") + QChar(0x00B0) + " (sign unknown)");
  EXPECT_EQ(gui::MakeOverlayTexts(rows.find(2), 2, 10).yaw, QString("yaw -20.0") + QChar(0x00B0));
}

}  // namespace
}  // namespace armmimic::test
