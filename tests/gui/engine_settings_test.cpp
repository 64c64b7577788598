// The engine parameter forms: every option of every engine's table has an editor, a change made
// through it reaches options() (the struct the CLI fills) and survives a QSettings round trip.
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QSpinBox>
#include <QTest>
#include <QToolButton>
#include <QWheelEvent>
#include <cmath>

#include "armmimic/engines/option_fields.h"
#include "engine_settings_panel.h"
#include "gui_fixture.h"

namespace armmimic::test {
namespace {

using gui::EngineSettingsPanel;

// A value of `f` other than `v`, one step away and inside the range.
template <typename O>
double Nudged(const OptionField<O>& f, double v) {
  if (f.kind == OptionKind::kBool) return v != 0 ? 0 : 1;
  if (f.kind == OptionKind::kEnum) return v + 1 <= f.max ? v + 1 : v - 1;
  return v + f.step <= f.max ? v + f.step : v - f.step;
}

// Changes the editor of `f` to `value` the way an operator does: type into a spin box, click a
// check box, pick a combo box entry.
void Edit(QWidget* editor, OptionKind kind, double value) {
  switch (kind) {
    case OptionKind::kInt: {
      auto* spin = qobject_cast<QSpinBox*>(editor);
      ASSERT_NE(spin, nullptr);
      spin->selectAll();
      QTest::keyClicks(spin, QString::number(std::lround(value)));
      QTest::keyClick(spin, Qt::Key_Enter);
      break;
    }
    case OptionKind::kDouble: {
      auto* spin = qobject_cast<QDoubleSpinBox*>(editor);
      ASSERT_NE(spin, nullptr);
      spin->selectAll();
      QTest::keyClicks(spin, spin->textFromValue(value));
      QTest::keyClick(spin, Qt::Key_Enter);
      break;
    }
    case OptionKind::kBool: {
      auto* box = qobject_cast<QCheckBox*>(editor);
      ASSERT_NE(box, nullptr);
      if (box->isChecked() != (value != 0)) box->click();
      break;
    }
    case OptionKind::kEnum: {
      auto* combo = qobject_cast<QComboBox*>(editor);
      ASSERT_NE(combo, nullptr);
      combo->setCurrentIndex(int(value));
      break;
    }
    case OptionKind::kText:
      FAIL() << "the engine forms show no text rows";
  }
}

class EngineSettingsTest : public GuiTest {
 protected:
  // Edits every shown field of `fields` through its widget; returns the number edited.
  template <typename O>
  int EditAll(EngineSettingsPanel& panel, EngineKind engine,
              const std::vector<OptionField<O>>& fields, O EngineOptions::*member) {
    int edited = 0;
    for (const OptionField<O>& f : fields) {
      SCOPED_TRACE(f.key);
      QWidget* editor = panel.parameterEditor(engine, QString::fromStdString(f.key));
      EXPECT_NE(editor, nullptr);
      if (!editor) continue;
      const double before = f.get(panel.options().engine.*member);
      EXPECT_DOUBLE_EQ(before, f.default_value);
      double after = Nudged(f, before);
      if (f.kind == OptionKind::kDouble) {  // what the spin box shows is what the operator sets
        const double scale = std::pow(10.0, f.decimals);
        after = std::round(after * scale) / scale;
      }
      Edit(editor, f.kind, after);
      const AnalysisOptions o = panel.options();
      EXPECT_NEAR(f.get(o.engine.*member), after, 1e-9);
      ++edited;
    }
    return edited;
  }

  template <typename O>
  void ExpectSame(const std::vector<OptionField<O>>& fields, const O& a, const O& b) {
    for (const OptionField<O>& f : fields) {
      EXPECT_DOUBLE_EQ(f.get(a), f.get(b)) << f.key;
    }
  }
};

TEST_F(EngineSettingsTest, EveryParameterIsEditableAndSurvivesSettings) {
  EngineSettingsPanel panel;
  panel.show();
  int advanced = 0;
  for (const auto& f : LkOptionFields()) advanced += f.group == OptionGroup::kAdvanced;
  ASSERT_GT(advanced, 20);
  // The advanced section is folded away until asked for.
  panel.findChild<QComboBox*>("engineCombo")->setCurrentIndex(int(EngineKind::kLk));
  QWidget* lk_advanced = panel.findChild<QWidget*>("lkAdvanced");
  ASSERT_NE(lk_advanced, nullptr);
  EXPECT_FALSE(lk_advanced->isVisibleTo(&panel));
  panel.advancedToggle(EngineKind::kLk)->click();
  EXPECT_TRUE(lk_advanced->isVisibleTo(&panel));

  const int n = EditAll(panel, EngineKind::kBgsub, BgsubOptionFields(), &EngineOptions::bgsub) +
                EditAll(panel, EngineKind::kLk, LkOptionFields(), &EngineOptions::lk) +
                EditAll(panel, EngineKind::kMarker, MarkerOptionFields(), &EngineOptions::marker) +
                EditAll(panel, EngineKind::kPose, PoseOptionFields(), &EngineOptions::pose) +
                EditAll(panel, EngineKind::kHybrid, HybridOptionFields(), &EngineOptions::hybrid);
  EXPECT_EQ(n, static_cast<int>(BgsubOptionFields().size() + LkOptionFields().size() +
                                MarkerOptionFields().size() + PoseOptionFields().size() +
                                HybridOptionFields().size()));
  const AnalysisOptions edited = panel.options();
  EXPECT_TRUE(edited.engine.bgsub.Check().ok()) << edited.engine.bgsub.Check().message();
  EXPECT_TRUE(edited.engine.lk.Check().ok()) << edited.engine.lk.Check().message();
  EXPECT_TRUE(edited.engine.marker.Check().ok()) << edited.engine.marker.Check().message();
  EXPECT_TRUE(edited.engine.hybrid.Check().ok()) << edited.engine.hybrid.Check().message();

  const QString ini = QString::fromStdString(tmp_.file("panel.ini"));
  {
    QSettings s(ini, QSettings::IniFormat);
    panel.save(s);
  }
  EngineSettingsPanel restored;
  QSettings s(ini, QSettings::IniFormat);
  restored.load(s);
  const AnalysisOptions back = restored.options();
  ExpectSame(BgsubOptionFields(), edited.engine.bgsub, back.engine.bgsub);
  ExpectSame(LkOptionFields(), edited.engine.lk, back.engine.lk);
  ExpectSame(MarkerOptionFields(), edited.engine.marker, back.engine.marker);
  ExpectSame(PoseOptionFields(), edited.engine.pose, back.engine.pose);
  ExpectSame(HybridOptionFields(), edited.engine.hybrid, back.engine.hybrid);
  EXPECT_EQ(restored.parameterEditor(EngineKind::kLk, "side")->property("currentText"),
            panel.parameterEditor(EngineKind::kLk, "side")->property("currentText"));
}

TEST_F(EngineSettingsTest, ValuesTheSpinBoxRoundsPassThroughExactly) {
  // 1/6 shows as 0.167; the analysis must still get 1/6, as the CLI does.
  EngineSettingsPanel panel;
  AnalysisOptions o;
  o.engine.lk.shoulder_inset = 1.0 / 6;
  o.engine.bgsub.shoulder_side = 1.0 / 7;
  panel.setOptions(o);
  EXPECT_EQ(panel.options().engine.lk.shoulder_inset, 1.0 / 6);
  EXPECT_EQ(panel.options().engine.bgsub.shoulder_side, 1.0 / 7);
  EXPECT_EQ(panel.options().engine.bgsub.straight_ratio, BgsubOptions().straight_ratio);
  // An edit replaces it.
  Edit(panel.parameterEditor(EngineKind::kLk, "shoulder_inset"), OptionKind::kDouble, 0.25);
  EXPECT_DOUBLE_EQ(panel.options().engine.lk.shoulder_inset, 0.25);
}

TEST_F(EngineSettingsTest, TheWheelScrollsPastUnfocusedEditors) {
  EngineSettingsPanel panel;
  panel.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
  auto* spin = qobject_cast<QSpinBox*>(panel.parameterEditor(EngineKind::kBgsub, "threshold"));
  ASSERT_NE(spin, nullptr);
  auto wheel = [&] {
    const QPointF at(spin->width() / 2.0, spin->height() / 2.0);
    QWheelEvent event(at, spin->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(spin, &event);
  };
  wheel();
  EXPECT_EQ(spin->value(), 45);  // passing over it while scrolling the form
  spin->setFocus();
  ASSERT_TRUE(WaitUntil([&] { return spin->hasFocus(); }, 2000));
  wheel();
  EXPECT_EQ(spin->value(), 46);  // the focused editor takes the wheel
}

TEST_F(EngineSettingsTest, OutOfRangeSettingsAreClampedToTheTable) {
  const QString ini = QString::fromStdString(tmp_.file("bad.ini"));
  {
    QSettings s(ini, QSettings::IniFormat);
    s.setValue("analysis/lk/max_corners", 999999);
    s.setValue("analysis/lk/side", "sideways");
    s.setValue("analysis/marker/low", "not a number");
  }
  EngineSettingsPanel panel;
  QSettings s(ini, QSettings::IniFormat);
  panel.load(s);
  const AnalysisOptions o = panel.options();
  EXPECT_EQ(o.engine.lk.max_corners, int(FindOptionField(LkOptionFields(), "max_corners")->max));
  EXPECT_EQ(o.engine.lk.side, LkArmSide::kAuto);
  EXPECT_EQ(o.engine.marker.low, MarkerOptions().low);
}

}  // namespace
}  // namespace armmimic::test
