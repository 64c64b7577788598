// The robot panel's fields against the robot tables: every number field that edits a row shows
// the row's decimals and default and offers no value the row's range refuses; the offsets of the
// joint maps show their rows' defaults; a value typed at a field's limit plans without a refusal
// from Check() about that field.
#include <QDoubleSpinBox>
#include <QTest>
#include <cmath>
#include <set>

#include "armmimic/robot/option_tables.h"
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

}  // namespace
}  // namespace armmimic::test
