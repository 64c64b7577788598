// The angle plot as the operator reads it: the degree labels stay readable at any height of the
// Angles dock.
#include <QChart>
#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QImage>
#include <QPalette>
#include <QStringList>
#include <QTest>

#include "angle_plot.h"
#include "gui_fixture.h"
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

}  // namespace
}  // namespace armmimic::test
