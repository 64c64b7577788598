// The robot panel's fields against the robot tables: every number field that edits a row shows
// the row's decimals and default and offers no value the row's range refuses; the offsets of the
// joint maps show their rows' defaults; a value typed at a field's limit plans without a refusal
// from Check() about that field; the Controller tab's fields are saved under their rows' keys,
// and the names earlier versions saved them under still load.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QTest>
#include <cmath>
#include <set>

#include "armmimic/robot/option_tables.h"
#include "armmimic/serial/port_table.h"
#include "gui_fixture.h"
#include "main_window.h"
#include "robot_option_keys.h"
#include "robot_panel.h"

namespace armmimic::test {
namespace {

class RobotOptionKeysTest : public GuiTest {};

// The number row `key` of `fields` (named "TABLE.KEY"), or nullptr.
template <typename O>
const OptionField<O>* NumberRow(const std::vector<OptionField<O>>& fields, const std::string& table,
                                const std::string& key) {
  if (key.rfind(table + ".", 0) != 0) return nullptr;
  const OptionField<O>* f = FindOptionField(fields, key.substr(table.size() + 1));
  return f && f->kind == OptionKind::kDouble ? f : nullptr;
}

template <typename O>
void ExpectFieldFollowsRow(const OptionField<O>& f, const QDoubleSpinBox* box) {
  EXPECT_EQ(box->decimals(), f.decimals);
  EXPECT_EQ(box->value(), f.default_value);
  if (f.min_exclusive) {
    EXPECT_GT(box->minimum(), f.min);
  } else {
    EXPECT_EQ(box->minimum(), f.min);
  }
  if (std::isinf(f.max)) {
    EXPECT_GT(box->maximum(), f.default_value);  // the form's own top
  } else {
    EXPECT_EQ(box->maximum(), f.max);
  }
}

TEST_F(RobotOptionKeysTest, NumberFieldsTakeTheirRowsDecimalsRangeAndDefault) {
  gui::MainWindow w;
  int checked = 0;
  std::set<std::string> offsets;
  for (QDoubleSpinBox* box : w.robotPanel()->findChildren<QDoubleSpinBox*>()) {
    const std::string key = box->property("optionKey").toString().toStdString();
    if (key.empty()) continue;  // not a table row (the simulator's speed)
    SCOPED_TRACE(key);
    if (const auto* f = NumberRow(robot::PlannerOptionFields(), "planner", key)) {
      ExpectFieldFollowsRow(*f, box);
      ++checked;
    } else if (const auto* s = NumberRow(robot::SendOptionFields(), "send", key)) {
      ExpectFieldFollowsRow(*s, box);
      ++checked;
    } else {
      // The offset of a joint map, a "SIGN,OFFSET" row with no range of its own: its default.
      const OptionField<robot::MappingOptions>* m =
          key.rfind("mapping.", 0) == 0
              ? FindOptionField(robot::MappingOptionFields(), key.substr(8))
              : nullptr;
      ASSERT_NE(m, nullptr) << "a number field for a row that is neither a number nor a map";
      robot::MappingOptions defaults;
      ASSERT_EQ(m->parse(m->default_text, &defaults), "");
      const robot::JointMap* maps[3] = {&defaults.j1, &defaults.j2, &defaults.j3};
      EXPECT_EQ(box->value(), maps[key.back() - '1']->offset_deg);
      offsets.insert(key);
    }
  }
  // cutoff, deadband, min interval, max gap; the prompt and motion timeouts.
  EXPECT_EQ(checked, 6);
  EXPECT_EQ(offsets, (std::set<std::string>{"mapping.j1", "mapping.j2", "mapping.j3"}));
}

TEST_F(RobotOptionKeysTest, APlannerFieldAtEitherEndOfItsRangeIsNotRefusedForIt) {
  gui::MainWindow w;
  for (QDoubleSpinBox* box : w.robotPanel()->findChildren<QDoubleSpinBox*>()) {
    const std::string key = box->property("optionKey").toString().toStdString();
    if (!NumberRow(robot::PlannerOptionFields(), "planner", key)) continue;
    SCOPED_TRACE(key);
    const double shown = box->value();
    for (const double end : {box->minimum(), box->maximum()}) {
      box->setValue(end);
      const Status s = w.robotPanel()->plannerOptions().Check();
      EXPECT_NE(s.key(), key) << end << ": " << s.message();
    }
    box->setValue(shown);
  }
}

TEST_F(RobotOptionKeysTest, TheControllerFieldsAreSavedUnderTheirTableKeys) {
  TempDir dir;
  const QString ini = QString::fromStdString(dir.file("settings.ini"));
  {
    gui::MainWindow w;
    auto* data_bits = w.robotPanel()->findChild<QComboBox*>("dataBitsCombo");
    auto* flow = w.robotPanel()->findChild<QComboBox*>("flowCombo");
    data_bits->setCurrentIndex(data_bits->findData(7));
    flow->setCurrentIndex(flow->findData(int(serial::FlowControl::kRtsCts)));
    w.robotPanel()->findChild<QDoubleSpinBox*>("promptTimeout")->setValue(2.5);
    QSettings s(ini, QSettings::IniFormat);
    s.setValue("robot/baud", 1200);  // an old name, dropped on save
    w.robotPanel()->save(s);
    s.beginGroup("robot");
    for (const auto& row : serial::PortOptionFields()) {
      EXPECT_TRUE(s.contains(QString::fromStdString("port." + row.key))) << row.key;
    }
    for (const auto& row : robot::SendOptionFields()) {
      EXPECT_TRUE(s.contains(QString::fromStdString("send." + row.key))) << row.key;
    }
    EXPECT_EQ(s.value("port.data_bits").toString(), "7");
    EXPECT_EQ(s.value("port.flow").toString(), "rtscts");
    EXPECT_EQ(s.value("send.prompt_timeout_s").toString(), "2.5");
    EXPECT_FALSE(s.contains("baud"));
  }
  gui::MainWindow w;
  QSettings s(ini, QSettings::IniFormat);
  w.robotPanel()->load(s);
  EXPECT_EQ(w.robotPanel()->findChild<QComboBox*>("dataBitsCombo")->currentData().toInt(), 7);
  EXPECT_EQ(w.robotPanel()->findChild<QDoubleSpinBox*>("promptTimeout")->value(), 2.5);
}

TEST_F(RobotOptionKeysTest, ControllerFieldsSavedUnderTheOldNamesStillLoad) {
  TempDir dir;
  const QString ini = QString::fromStdString(dir.file("old.ini"));
  {
    QSettings s(ini, QSettings::IniFormat);
    s.beginGroup("robot");
    s.setValue("dataBits", 7);
    s.setValue("parity", "E");
    s.setValue("flow", "xonxoff");
    s.setValue("motionTimeout", 90.0);
    s.setValue("port", "/dev/ttyUSB3");
  }
  gui::MainWindow w;
  QSettings s(ini, QSettings::IniFormat);
  w.robotPanel()->load(s);
  const serial::PortSettings p = [&] {
    auto* panel = w.robotPanel();
    serial::PortSettings out;
    out.data_bits = panel->findChild<QComboBox*>("dataBitsCombo")->currentData().toInt();
    out.parity = panel->findChild<QComboBox*>("parityCombo")->currentData().toChar().toLatin1();
    out.flow = static_cast<serial::FlowControl>(
        panel->findChild<QComboBox*>("flowCombo")->currentData().toInt());
    return out;
  }();
  EXPECT_EQ(p.data_bits, 7);
  EXPECT_EQ(p.parity, 'E');
  EXPECT_EQ(p.flow, serial::FlowControl::kXonXoff);
  EXPECT_EQ(w.robotPanel()->findChild<QDoubleSpinBox*>("motionTimeout")->value(), 90.0);
  EXPECT_EQ(w.robotPanel()->findChild<QComboBox*>("portCombo")->currentText(), "/dev/ttyUSB3");
}

}  // namespace
}  // namespace armmimic::test
