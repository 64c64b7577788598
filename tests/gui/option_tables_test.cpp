// Every option table against the three places a setting shows: the command line (its flag is
// registered, with help; the engines' keys are listed for --param), the GUI (a field named by
// the key) and the file header a run writes (the key is recorded and reads back the same).
// Length: the robot tables' test walks the plan, mimic and send help and the VAL header in one
// body, since the three share the planned program it reads back.
#include <QApplication>
#include <QSettings>
#include <QTest>
#include <QVariantList>
#include <set>
#include <sstream>

#include "armmimic/core/angle_file.h"
#include "armmimic/engines/option_fields.h"
#include "armmimic/engines/run_record.h"
#include "armmimic/robot/option_tables.h"
#include "armmimic/robot/val_program.h"
#include "armmimic/serial/port_table.h"
#include "engine_settings_panel.h"
#include "gui_fixture.h"
#include "main_window.h"
#include "robot_option_keys.h"
#include "robot_panel.h"

namespace armmimic::test {
namespace {

// The help text of `command` (armmimic-cli COMMAND --help).
std::string Help(const std::string& command) {
  const CliResult r = RunCli({command, "--help"});
  EXPECT_EQ(r.exit_code, 0) << command << ": " << r.err;
  return r.out;
}

// The help line of `flag` in `help` ("  --cutoff HZ   ..."), "" when it is not listed.
std::string HelpLine(const std::string& help, const std::string& flag) {
  std::istringstream in(help);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("  " + flag + " ", 0) == 0 || line == "  " + flag) return line;
  }
  return "";
}

// A value of `f` other than `v`, inside its range.
template <typename O>
double OtherValue(const OptionField<O>& f, double v) {
  if (f.kind == OptionKind::kBool) return v != 0 ? 0 : 1;
  if (f.kind == OptionKind::kEnum) return v + 1 <= f.max ? v + 1 : v - 1;
  const double step = f.kind == OptionKind::kInt ? f.step : std::max(f.step, 0.01);
  return v + step <= f.max ? v + step : v - step;
}

class OptionTablesTest : public GuiTest {
 protected:
  // An engine's table: the CLI lists every key for --param and registers each row's flag; the
  // engine's form has a field named "ENGINE.KEY" for every row it shows; the header of a run
  // records every key, and a changed value of each reads back the same.
  template <typename O>
  void CheckEngineTable(const std::vector<OptionField<O>>& fields, EngineKind kind,
                        O EngineOptions::*member, gui::EngineSettingsPanel& panel) {
    const std::string engine = EngineName(kind);
    const std::string analyze = Help("analyze");
    const std::string mimic = Help("mimic");
    AnalysisOptions changed;
    changed.engine.kind = kind;
    const O defaults;
    for (const OptionField<O>& f : fields) {
      const std::string key = engine + "." + f.key;
      const std::string listed = key + "=" + OptionValueText(f, f.get(defaults));
      EXPECT_NE(analyze.find(listed), std::string::npos) << listed << " in analyze --help";
      EXPECT_NE(mimic.find(listed), std::string::npos) << listed << " in mimic --help";
      if (!f.flag.empty()) {
        EXPECT_NE(HelpLine(analyze, f.flag), "") << f.flag << " (" << key << ") in analyze";
        EXPECT_NE(HelpLine(mimic, f.flag), "") << f.flag << " (" << key << ") in mimic";
      }
      if (f.group != OptionGroup::kInput) {
        EXPECT_NE(panel.findChild<QWidget*>(QString::fromStdString(key)), nullptr)
            << "no field named " << key;
      }
      f.set(changed.engine.*member, OtherValue(f, f.get(defaults)));
    }
    // The header as written by a run, read back.
    AngleMeta meta = RunRecordMeta(changed);
    meta.insert(meta.begin(), {"engine", engine});  // the run's first meta key
    AnalysisOptions back;
    const Status read = RunFromMeta(meta, "header", &back);
    ASSERT_TRUE(read.ok()) << read.message();
    std::set<std::string> recorded;
    for (const auto& [k, v] : meta) recorded.insert(k);
    for (const OptionField<O>& f : fields) {
      EXPECT_TRUE(recorded.count(engine + "." + f.key)) << engine << "." << f.key;
      EXPECT_EQ(f.get(back.engine.*member), f.get(changed.engine.*member)) << f.key;
    }
  }
};

TEST_F(OptionTablesTest, EngineTablesAgreeWithTheCliTheFormsAndTheHeader) {
  gui::EngineSettingsPanel panel;
  CheckEngineTable(BgsubOptionFields(), EngineKind::kBgsub, &EngineOptions::bgsub, panel);
  CheckEngineTable(LkOptionFields(), EngineKind::kLk, &EngineOptions::lk, panel);
  CheckEngineTable(MarkerOptionFields(), EngineKind::kMarker, &EngineOptions::marker, panel);
  CheckEngineTable(PoseOptionFields(), EngineKind::kPose, &EngineOptions::pose, panel);
}

TEST_F(OptionTablesTest, AnAnalysisRecordsEveryKeyOfItsEngine) {
  const GuiScenes& s = scenes();
  TempDir dir;
  const CliResult r =
      RunCli({"analyze", s.video(), "-o", dir.file("a.tsv"), "--engine", "bgsub", "--background",
              s.background(), "--arm-length", s.arm_length(), "--start",
              std::to_string(s.background_frames), "--standstill-frames",
              std::to_string(s.standstill_frames), "--param", "bgsub.closing_size=7"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  AnalysisOptions back;
  ASSERT_TRUE(ReadRunRecord(dir.file("a.tsv"), &back).ok());
  AnalysisOptions expected = s.BgsubProtocol();
  expected.engine.bgsub.closing_size = 7;
  for (const auto& f : BgsubOptionFields()) {
    EXPECT_EQ(f.get(back.engine.bgsub), f.get(expected.engine.bgsub)) << f.key;
  }
}

// The robot tables' rows the robot panel does not offer: set on the command line only. (The
// link's settings come from the controller profile, which both shells read.)
const std::set<std::string>& NotInThePanel() {
  static const std::set<std::string> keys = {
      "planner.gap",        "planner.max_jump_deg_s", "planner.max_interval_s",
      "planner.speed",      "planner.fallback_fps",   "mapping.j2_elevation",
      "mapping.j3_flexion", "mapping.hold_deg",
  };
  return keys;
}

template <typename O>
void CheckRobotTable(const std::vector<OptionField<O>>& fields, const std::string& table,
                     const std::string& command, QWidget* panel) {
  const std::string help = Help(command);
  for (const OptionField<O>& f : fields) {
    const std::string key = table + "." + f.key;
    ASSERT_FALSE(f.flag.empty()) << key << " has no flag";
    EXPECT_NE(HelpLine(help, f.flag), "") << f.flag << " (" << key << ") in " << command;
    EXPECT_FALSE(f.help.empty()) << key;
    QWidget* field = gui::RobotOptionField(panel, QString::fromStdString(key));
    if (NotInThePanel().count(key)) {
      EXPECT_EQ(field, nullptr) << key << " is in the panel: drop it from NotInThePanel";
    } else {
      EXPECT_NE(field, nullptr) << "no robot panel field for " << key;
    }
  }
}

TEST_F(OptionTablesTest, RobotTablesAgreeWithTheCliTheRobotPanelAndTheProgramHeader) {
  gui::MainWindow w;
  CheckRobotTable(robot::PlannerOptionFields(), "planner", "plan", &w);
  CheckRobotTable(robot::MappingOptionFields(), "mapping", "plan", &w);
  CheckRobotTable(robot::LimitsOptionFields(), "limits", "plan", &w);
  CheckRobotTable(robot::MappingOptionFields(), "mapping", "mimic", &w);
  CheckRobotTable(robot::LimitsOptionFields(), "limits", "mimic", &w);
  CheckRobotTable(robot::LimitsOptionFields(), "limits", "send", &w);
  CheckRobotTable(serial::PortOptionFields(), "port", "send", &w);
  CheckRobotTable(serial::PortOptionFields(), "port", "mimic", &w);

  // A plan with a changed value for every flag records each key; reading the header back gives
  // the options the flags describe.
  TempDir dir;
  {
    AngleFileWriter out;
    ASSERT_TRUE(out.Open(dir.file("a.tsv"), {{"engine", "bgsub"}, {"fps", "10"}}, false).ok());
    for (int i = 0; i < 30; ++i) {
      AngleRow row;
      row.frame = i;
      row.time_s = i / 10.0;
      row.status = RowStatus::kOk;
      row.upper_deg = -90 + i;
      row.bend_deg = -i;
      row.fore_deg = row.upper_deg + row.bend_deg;
      row.yaw_deg = 5;
      ASSERT_TRUE(out.Write(row).ok());
    }
    ASSERT_TRUE(out.Commit().ok());
  }
  const CliResult r = RunCli({"plan",
                              dir.file("a.tsv"),
                              "-o",
                              dir.file("p.val"),
                              "--cutoff",
                              "2.5",
                              "--max-gap-s",
                              "0.75",
                              "--gap",
                              "hold",
                              "--max-jump",
                              "900",
                              "--deadband",
                              "1.5",
                              "--min-interval",
                              "0.3",
                              "--max-interval",
                              "1.25",
                              "--clamp",
                              "--on-speed",
                              "stretch",
                              "--fallback-fps",
                              "2",
                              "--map-j1",
                              "-1,5",
                              "--map-j2",
                              "-1,-10",
                              "--map-j3",
                              "+1,-20",
                              "--mirror",
                              "--j2-source",
                              "upper",
                              "--j3-source",
                              "bend",
                              "--hold",
                              "1,2,3",
                              "--limits",
                              "J1=-150:150,J2=-190:10",
                              "--speed-limit",
                              "40,41,42,80,81,82"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  robot::ValProgram program;
  ASSERT_TRUE(robot::ReadValProgram(dir.file("p.val"), &program).ok());
  robot::PlannerOptions back;
  int recorded = 0;
  for (const auto& [key, value] : program.header) {
    if (key.rfind("planner.", 0) && key.rfind("mapping.", 0) && key.rfind("limits.", 0)) continue;
    ASSERT_TRUE(robot::SetPlannerSetting(key + "=" + value, &back).ok()) << key << "=" << value;
    ++recorded;
  }
  EXPECT_EQ(recorded, static_cast<int>(robot::PlannerOptionFields().size() +
                                       robot::MappingOptionFields().size() +
                                       robot::LimitsOptionFields().size()));
  robot::PlannerOptions expected;
  expected.cutoff_hz = 2.5;
  expected.max_gap_s = 0.75;
  expected.gap = robot::GapMode::kHold;
  expected.max_jump_deg_s = 900;
  expected.deadband_deg = 1.5;
  expected.min_interval_s = 0.3;
  expected.max_interval_s = 1.25;
  expected.clamp = true;
  expected.fallback_fps = 2;
  expected.mapping.j1 = {-1, 5};
  expected.mapping.j2 = {-1, -10};
  expected.mapping.j3 = {1, -20};
  expected.mapping.mirror = true;
  expected.mapping.j2_elevation = false;
  expected.mapping.j3_flexion = false;
  expected.mapping.hold_deg = {0, 0, 0, 1, 2, 3};
  expected.limits.min_deg[0] = -150;
  expected.limits.max_deg[0] = 150;
  expected.limits.min_deg[1] = -190;
  expected.limits.max_deg[1] = 10;
  expected.limits.max_speed_deg_s = {40, 41, 42, 80, 81, 82};
  EXPECT_EQ(robot::DescribePlannerSettings(back), robot::DescribePlannerSettings(expected));
}

TEST_F(OptionTablesTest, TheRobotPanelSavesItsFieldsUnderTheirTableKeys) {
  TempDir dir;
  const QString ini = QString::fromStdString(dir.file("settings.ini"));
  robot::PlannerOptions edited;
  edited.cutoff_hz = 2.25;
  edited.deadband_deg = 1.5;
  edited.min_interval_s = 0.4;
  edited.max_interval_s = 1.0;
  edited.max_gap_s = 0.75;
  edited.clamp = true;
  edited.mapping.mirror = true;
  edited.mapping.j2 = {-1, -12.5};
  edited.limits.min_deg[1] = -150;
  edited.limits.max_speed_deg_s[5] = 60;
  std::string saved;
  {
    gui::MainWindow w;
    w.robotPanel()->setPlannerOptions(edited);
    saved = robot::DescribePlannerSettings(w.robotPanel()->plannerOptions());
    QSettings s(ini, QSettings::IniFormat);
    w.robotPanel()->save(s);
    s.beginGroup("robot");
    int keys = 0;
    auto expect_keys = [&](const auto& fields, const std::string& table) {
      for (const auto& f : fields) {
        const std::string key = table + "." + f.key;
        if (!gui::RobotOptionField(&w, QString::fromStdString(key))) continue;
        EXPECT_TRUE(s.contains(QString::fromStdString(key))) << key << " not saved";
        ++keys;
      }
    };
    expect_keys(robot::PlannerOptionFields(), "planner");
    expect_keys(robot::MappingOptionFields(), "mapping");
    expect_keys(robot::LimitsOptionFields(), "limits");
    EXPECT_EQ(keys, 12);  // every plan field of the panel (NotInThePanel lists the others)
    EXPECT_FALSE(s.contains("cutoff"));  // no second name for a setting
  }
  gui::MainWindow w;
  QSettings s(ini, QSettings::IniFormat);
  w.robotPanel()->load(s);
  EXPECT_EQ(robot::DescribePlannerSettings(w.robotPanel()->plannerOptions()), saved);
  EXPECT_NE(saved, robot::DescribePlannerSettings(robot::PlannerOptions()));
}

TEST_F(OptionTablesTest, SettingsSavedUnderTheOldNamesStillLoad) {
  TempDir dir;
  const QString ini = QString::fromStdString(dir.file("old.ini"));
  {
    QSettings s(ini, QSettings::IniFormat);
    s.beginGroup("robot");
    s.setValue("cutoff", 1.75);
    s.setValue("clamp", true);
    s.setValue("j2/offset", -7.5);
    s.setValue("limitsMin", QVariantList{-150, -190, -225, -266, -100, -266});
    s.setValue("limitsMax", QVariantList{150, 10, 45, 266, 100, 266});
    s.setValue("speedLimits", QVariantList{40, 40, 40, 80, 80, 80});
  }
  gui::MainWindow w;
  QSettings s(ini, QSettings::IniFormat);
  w.robotPanel()->load(s);
  const robot::PlannerOptions o = w.robotPanel()->plannerOptions();
  EXPECT_EQ(o.cutoff_hz, 1.75);
  EXPECT_TRUE(o.clamp);
  EXPECT_EQ(o.mapping.j2.offset_deg, -7.5);
  EXPECT_EQ(o.limits.min_deg[0], -150);
  EXPECT_EQ(o.limits.max_deg[1], 10);
  EXPECT_EQ(o.limits.max_speed_deg_s[3], 80);
}

}  // namespace
}  // namespace armmimic::test
