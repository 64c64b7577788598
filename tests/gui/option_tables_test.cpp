// Every option table against the three places a setting shows: the command line (its flag is
// registered with the row's help and default; the engines' keys are listed for --param), the
// GUI (a field named by the key) and the file a run writes (the key is recorded and reads back
// the same). A row a place does not show is listed with the reason (AbsentRows,
// EngineFlagsWithTheirOwnHelp).
// Length: one walk over every table, with the list of rows a place does not show and why; the
// robot tables share the planned program the walk reads back.
#include <QApplication>
#include <QSettings>
#include <QTest>
#include <QVariantList>
#include <map>
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

// The engine rows whose flag's help is not the row's own, with the reason.
const std::map<std::string, std::string>& EngineFlagsWithTheirOwnHelp() {
  static const std::map<std::string, std::string> rows = {
      {"bgsub.thesis_mode", "--thesis sets every engine's thesis_mode; its help speaks for all"},
      {"lk.thesis_mode", "--thesis: see bgsub.thesis_mode"},
      {"marker.thesis_mode", "--thesis: see bgsub.thesis_mode"},
      {"lk.standstill_frames",
       "--standstill-frames sets bgsub's and lk's rows, with bgsub's help; the two rows' "
       "defaults and ranges are checked equal"},
  };
  return rows;
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
        const std::string line = HelpLine(analyze, f.flag);
        EXPECT_NE(line, "") << f.flag << " (" << key << ") in analyze";
        if (key == "pose.side") {
          // One robot follows one arm: mimic offers left and right only.
          EXPECT_EQ(HelpLine(mimic, f.flag).find("both"), std::string::npos) << "mimic --side";
        } else {
          EXPECT_EQ(HelpLine(mimic, f.flag), line) << f.flag << " (" << key << ") in mimic";
        }
        if (!EngineFlagsWithTheirOwnHelp().count(key)) {
          // The flag's help and default are the row's.
          EXPECT_NE(line.find(f.help), std::string::npos) << key << ": " << line;
          if (f.kind != OptionKind::kBool) {
            EXPECT_NE(line.find("(default " + OptionDefaultText(f) + ")"), std::string::npos)
                << key << ": " << line;
          }
        }
      }
      EXPECT_NE(panel.findChild<QWidget*>(QString::fromStdString(key)), nullptr)
          << "no field named " << key;
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
  // One flag for two rows: the rows agree on what the flag offers.
  const auto& bgsub = *FindOptionField(BgsubOptionFields(), "standstill_frames");
  const auto& lk = *FindOptionField(LkOptionFields(), "standstill_frames");
  EXPECT_EQ(bgsub.flag, lk.flag);
  EXPECT_EQ(bgsub.default_value, lk.default_value);
  EXPECT_EQ(bgsub.min, lk.min);
  EXPECT_EQ(bgsub.max, lk.max);
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

// The robot-side rows that one of the three places does not show, with the reason for each
// place ("": the row shows there, and the walk checks it). A row missing from a place without a
// reason here fails, and so does a reason for a place where the row does show, so the list
// cannot go stale. The files a run writes: plan's VAL program (its settings line, its "mode="
// header key, its EDIT line).
struct Absent {
  const char* cli = "";    // why no command offers a flag with the row's help and default
  const char* panel = "";  // why the GUI has no field for it
  const char* file = "";   // why no file a run writes records it
};

constexpr const char* kPortNotInAFile =
    "where a run goes, not how it plans: the line settings are in no file (mimic's journal "
    "names the device only)";
constexpr const char* kLinkFromProfile =
    "read from the controller profile file, which both shells choose (send --profile, the "
    "Controller tab)";

const std::map<std::string, Absent>& AbsentRows() {
  static const std::map<std::string, Absent> rows = {
      {"planner.gap", {"", "the panel fills short gaps by interpolation (the default)", ""}},
      {"planner.max_jump_deg_s", {"", "the panel flags jumps at the default speed", ""}},
      {"planner.max_interval_s", {"", "the panel keeps the default keyframe interval", ""}},
      {"planner.speed", {"", "the panel stretches a too fast step (the default)", ""}},
      {"planner.fallback_fps", {"", "the panel keeps the default fallback rate", ""}},
      {"mapping.j2_elevation", {"", "the panel maps J2 from the elevation (the default)", ""}},
      {"mapping.j3_flexion", {"", "the panel maps J3 from the flexion (the default)", ""}},
      {"mapping.arm_3d",
       {"", "the panel maps an arm from its 3-D columns where the file has them (the default)",
        ""}},
      {"mapping.hold_deg", {"", "the panel holds J4..J6 at 0 (the default)", ""}},
      {"limits.min_deg",
       {"--limits sets both limits rows in its own J<n>=MIN:MAX form; its help gives both rows' "
        "defaults in that form",
        "", ""}},
      {"limits.max_deg", {"--limits: see limits.min_deg", "", ""}},
      {"port.port", {"", "", kPortNotInAFile}},
      {"port.baud", {"", "", kPortNotInAFile}},
      {"port.data_bits", {"", "", kPortNotInAFile}},
      {"port.parity", {"", "", kPortNotInAFile}},
      {"port.stop_bits", {"", "", kPortNotInAFile}},
      {"port.flow", {"", "", kPortNotInAFile}},
      {"link.echo", {kLinkFromProfile, kLinkFromProfile, kLinkFromProfile}},
      {"link.wake_attempts", {kLinkFromProfile, kLinkFromProfile, kLinkFromProfile}},
      {"link.wake_timeout_s", {kLinkFromProfile, kLinkFromProfile, kLinkFromProfile}},
      {"link.prompt_settle_s", {kLinkFromProfile, kLinkFromProfile, kLinkFromProfile}},
      {"send.profile_path",
       {"", "",
        "a send writes only its journal (the lines acknowledged); the program's header "
        "names the profile it was planned for, not a file"}},
      {"send.prompt_timeout_s",
       {"", "", "a send writes only its journal (the lines acknowledged), not how long it waited"}},
      {"send.motion_timeout_s",
       {"", "", "a send writes only its journal (the lines acknowledged), not how long it waited"}},
      {"live.stale_after_s",
       {"", "the Mimic panel holds the robot after the default time without a measured frame",
        "mimic's journal and latency log record what was sent and when, not the hold rule"}},
      {"source.kind",
       {"", "the panel plans the angles shown, whose kind it reads from their file (auto)",
        "the program's header names the angle file and its engine, from which the kind follows"}},
      {"profile.mode", {"", "the panel sends in the mode of the controller profile it shows", ""}},
      {"profile.program_name",
       {"", "the panel names the program as the controller profile it shows does", ""}},
  };
  return rows;
}

Absent AbsentFor(const std::string& key) {
  const auto it = AbsentRows().find(key);
  return it == AbsentRows().end() ? Absent() : it->second;
}

// The keys a table's rows show in the file `plan` wrote (see RobotTablesAgree...).
std::set<std::string>& RecordedInTheProgram() {
  static std::set<std::string> keys;
  return keys;
}

// Every row of a robot-side table against `commands` (each registers the row's flag with the
// row's help and default), the robot panel (a field carries the key) and the keys the planned
// program records, unless AbsentRows gives the reason.
template <typename O>
void CheckRobotTable(const std::vector<OptionField<O>>& fields, const std::string& table,
                     const std::vector<std::string>& commands, QWidget* panel) {
  for (const OptionField<O>& f : fields) {
    const std::string key = table + "." + f.key;
    SCOPED_TRACE(key);
    const Absent absent = AbsentFor(key);
    EXPECT_FALSE(f.help.empty());
    if (*absent.cli) {
      EXPECT_TRUE(f.flag.empty() || key.rfind("limits.", 0) == 0) << "a flag: " << f.flag;
      for (const std::string& command : commands) {
        if (!f.flag.empty()) {
          EXPECT_NE(HelpLine(Help(command), f.flag), "") << command;
        }
      }
    } else {
      ASSERT_FALSE(f.flag.empty()) << key << " has no flag";
      for (const std::string& command : commands) {
        const std::string line = HelpLine(Help(command), f.flag);
        EXPECT_NE(line, "") << f.flag << " in " << command;
        EXPECT_NE(line.find(f.help), std::string::npos) << command << ": " << line;
        const std::string def = OptionDefaultText(f);
        if (f.kind != OptionKind::kBool && !def.empty()) {
          EXPECT_NE(line.find("(default " + def), std::string::npos) << command << ": " << line;
        }
      }
    }
    QWidget* field = gui::RobotOptionField(panel, QString::fromStdString(key));
    if (*absent.panel) {
      EXPECT_EQ(field, nullptr) << key << " is in the panel: drop its panel reason";
    } else {
      EXPECT_NE(field, nullptr) << "no robot panel field for " << key;
    }
    EXPECT_EQ(RecordedInTheProgram().count(key), *absent.file ? 0u : 1u)
        << key << (*absent.file ? " is recorded: drop its file reason" : " is not recorded");
  }
}

// A 30-row angle file for `plan`.
void WriteAngles(const std::string& path) {
  AngleFileWriter out;
  ASSERT_TRUE(out.Open(path, {{"engine", "bgsub"}, {"fps", "10"}}, false).ok());
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

TEST_F(OptionTablesTest, RobotTablesAgreeWithTheCliTheRobotPanelAndTheProgramHeader) {
  // A plan with a changed value for every flag records each key; reading the header back gives
  // the options the flags describe.
  TempDir dir;
  WriteAngles(dir.file("a.tsv"));
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
                              "40,41,42,80,81,82",
                              "--mode",
                              "program",
                              "--program-name",
                              "ARM2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  robot::ValProgram program;
  ASSERT_TRUE(robot::ReadValProgram(dir.file("p.val"), &program).ok());
  robot::PlannerOptions back;
  std::set<std::string>& recorded = RecordedInTheProgram();
  recorded.clear();
  for (const auto& [key, value] : program.header) {
    if (key.rfind("planner.", 0) && key.rfind("mapping.", 0) && key.rfind("limits.", 0)) continue;
    ASSERT_TRUE(robot::SetPlannerSetting(key + "=" + value, &back).ok()) << key << "=" << value;
    recorded.insert(key);
  }
  // The profile's two overrides: the header's mode, the program's name in its EDIT line.
  EXPECT_EQ(program.header["mode"], "program");
  if (program.header["mode"] == "program") recorded.insert("profile.mode");
  for (const robot::ValLine& line : program.lines) {
    if (line.text == "EDIT ARM2") recorded.insert("profile.program_name");
  }

  gui::MainWindow w;
  CheckRobotTable(robot::PlannerOptionFields(), "planner", {"plan"}, &w);
  CheckRobotTable(robot::MappingOptionFields(), "mapping", {"plan", "mimic"}, &w);
  CheckRobotTable(robot::LimitsOptionFields(), "limits", {"plan", "mimic", "send"}, &w);
  CheckRobotTable(robot::LinkOptionFields(), "link", {}, &w);
  CheckRobotTable(serial::PortOptionFields(), "port", {"send", "mimic"}, &w);
  CheckRobotTable(robot::SendOptionFields(), "send", {"send"}, &w);
  CheckRobotTable(robot::LiveStreamOptionFields(), "live", {"mimic"}, &w);
  CheckRobotTable(robot::ProfileOptionFields(), "profile", {"plan"}, &w);
  CheckRobotTable(robot::SourceOptionFields(), "source", {"plan"}, &w);
  // The profile file plan and mimic read too.
  for (const char* command : {"plan", "mimic"}) {
    const auto& profile = *FindOptionField(robot::SendOptionFields(), "profile_path");
    EXPECT_NE(HelpLine(Help(command), profile.flag).find(profile.help), std::string::npos)
        << command;
  }
  for (const auto& [key, absent] : AbsentRows()) {
    EXPECT_TRUE(*absent.cli || *absent.panel || *absent.file) << key << ": no reason given";
  }

  EXPECT_EQ(recorded.size(), robot::PlannerOptionFields().size() +
                                 robot::MappingOptionFields().size() +
                                 robot::LimitsOptionFields().size() + 2);
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
    EXPECT_EQ(keys, 12);  // every plan field of the panel (AbsentRows lists the others)
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
