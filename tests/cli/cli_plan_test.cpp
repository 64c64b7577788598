// armmimic-cli plan: angle files in, VAL programs out, refusals and usage errors.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"
#include "test_util.h"

namespace armmimic {
namespace {

// An ordinary recording: the arm hangs, rises on the left side of the image (through the
// horizontal at 180) to straight up, flexes the elbow to 150 with a negative 2-D bend, and yaw
// is measured only while the arm is straight. A few frames are lost.
void WriteRecording(const std::string& path) {
  AngleFileWriter w;
  ASSERT_TRUE(
      w.Open(path, {{"engine", "bgsub"}, {"source", "rec.avi"}, {"fps", "30"}}, false).ok());
  for (int i = 0; i < 300; ++i) {
    const double t = i / 30.0;
    AngleRow r;
    r.frame = 105 + i;
    r.time_s = 3.5 + t;
    r.status = (i >= 100 && i < 104) ? RowStatus::kLost : RowStatus::kOk;
    if (r.ok()) {
      const double s = 0.5 * (1 - std::cos(kPi * t / 10));  // 0 -> 1 over 10 s
      r.upper_deg = Wrap180(-90 - 180 * s);                 // -90, -180 (=180), 90
      r.bend_deg = i < 150 ? 0 : -150 * (i - 150) / 150.0;
      r.fore_deg = Wrap180(r.upper_deg + r.bend_deg);
      r.yaw_deg = i < 150 ? 20 * s : kNaN;
    }
    ASSERT_TRUE(w.Write(r).ok());
  }
  ASSERT_TRUE(w.Commit().ok());
}

std::vector<std::string> SentLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string l;
  while (std::getline(in, l)) {
    if (!l.empty() && l[0] != ';') out.push_back(l);
  }
  return out;
}

// The six numbers of "... #PPOINT(a,b,c,d,e,f)".
std::vector<double> Ppoint(const std::string& line) {
  std::vector<double> v;
  const auto open = line.find('(');
  std::istringstream in(line.substr(open + 1, line.size() - open - 2));
  std::string part;
  while (std::getline(in, part, ',')) v.push_back(std::stod(part));
  return v;
}

TEST(CliPlan, OrdinaryRecordingPlansWithNoFlagsInsideTheLimits) {
  test::TempDir dir;
  WriteRecording(dir.file("a.tsv"));
  const auto r = test::RunCli({"plan", dir.file("a.tsv"), "-o", dir.file("p.val")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("keyframes from 300 of 300 rows"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("J2 used ["), std::string::npos);
  const std::string text = test::ReadFile(dir.file("p.val"));
  EXPECT_EQ(text.rfind("; armmimic VAL program v1\n; source=", 0), 0u);
  EXPECT_NE(text.find("; mapping=arm j1=+yaw+0.00 j2=-elevation+0.00"), std::string::npos);
  EXPECT_NE(text.find("; limits_min_deg=-160.00,-200.00,-225.00"), std::string::npos);
  const auto lines = SentLines(text);
  ASSERT_GT(lines.size(), 10u);
  EXPECT_EQ(lines[0], "SPEED 75");
  const double lo[6] = {-160, -200, -225, -266, -100, -266};
  const double hi[6] = {160, 20, 45, 266, 100, 266};
  double j2_min = 0, j3_min = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    EXPECT_LE(lines[i].size(), 80u);
    ASSERT_EQ(lines[i].rfind("DO MOVE #PPOINT(", 0), 0u) << lines[i];
    const auto q = Ppoint(lines[i]);
    ASSERT_EQ(q.size(), 6u);
    for (int j = 0; j < 6; ++j) {
      EXPECT_GE(q[j], lo[j]) << lines[i];
      EXPECT_LE(q[j], hi[j]) << lines[i];
    }
    j2_min = std::min(j2_min, q[1]);
    j3_min = std::min(j3_min, q[2]);
  }
  EXPECT_LT(j2_min, -175);  // raised straight up
  EXPECT_LT(j3_min, -145);  // elbow flexed to 150
  // Rounds trip to 10 s of video: at most 5 moves a second.
  EXPECT_LE(lines.size() - 1, 52u);
}

TEST(CliPlan, MarkerFilesMapBendToJ2AndProgramModeUploads) {
  test::TempDir dir;
  AngleFileWriter w;
  ASSERT_TRUE(w.Open(dir.file("m.tsv"), {{"engine", "marker"}}, true).ok());
  for (int i = 0; i < 5; ++i) {
    AngleRow r;
    r.frame = i;
    r.time_s = 0;  // images: no times
    r.status = RowStatus::kOk;
    r.yaw_deg = 10;
    r.bend_deg = 10 * i;
    r.file = "img_" + std::to_string(i) + ".png";
    ASSERT_TRUE(w.Write(r).ok());
  }
  ASSERT_TRUE(w.Commit().ok());
  const auto r = test::RunCli({"plan", dir.file("m.tsv"), "-o", dir.file("m.val"), "--cutoff", "0",
                               "--mode", "program", "--program-name", "ARM2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto lines = SentLines(test::ReadFile(dir.file("m.val")));
  ASSERT_GE(lines.size(), 5u);
  EXPECT_EQ(lines[1], "EDIT ARM2");
  EXPECT_EQ(lines[2], "MOVE #PPOINT(10.00,-90.00,0.00,0.00,0.00,0.00)");
  EXPECT_EQ(lines[lines.size() - 3], "MOVE #PPOINT(10.00,-130.00,0.00,0.00,0.00,0.00)");
  EXPECT_EQ(lines.back(), "EXECUTE ARM2");
}

// --source marker plans a file whose header does not say its engine with the marker mapping
// (J2 = -bend - 90), where auto would take it for an arm file.
TEST(CliPlan, SourceChoosesTheMappingOfAFileThatDoesNotSayItsEngine) {
  test::TempDir dir;
  AngleFileWriter w;
  ASSERT_TRUE(w.Open(dir.file("j.tsv"), {{"fps", "10"}}, false).ok());
  for (int i = 0; i < 5; ++i) {
    AngleRow r;
    r.frame = i;
    r.time_s = i / 10.0;
    r.status = RowStatus::kOk;
    r.yaw_deg = 10;
    r.bend_deg = 0;
    r.upper_deg = -90;
    r.fore_deg = -90;
    ASSERT_TRUE(w.Write(r).ok());
  }
  ASSERT_TRUE(w.Commit().ok());
  auto r = test::RunCli(
      {"plan", dir.file("j.tsv"), "-o", dir.file("m.val"), "--cutoff", "0", "--source", "marker"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("marker"), std::string::npos) << r.out;
  auto lines = SentLines(test::ReadFile(dir.file("m.val")));
  ASSERT_GE(lines.size(), 2u);
  EXPECT_NE(lines[1].find("#PPOINT(10.00,-90.00,0.00"), std::string::npos) << lines[1];
  r = test::RunCli({"plan", dir.file("j.tsv"), "-o", dir.file("a.val"), "--cutoff", "0"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("arm"), std::string::npos) << r.out;
  lines = SentLines(test::ReadFile(dir.file("a.val")));
  ASSERT_GE(lines.size(), 2u);
  EXPECT_NE(lines[1].find("#PPOINT(10.00,0.00,0.00"), std::string::npos) << lines[1];
}

TEST(CliPlan, RefusalsListTheFramesAndLeaveNoFile) {
  test::TempDir dir;
  WriteRecording(dir.file("a.tsv"));
  auto r = test::RunCli({"plan", dir.file("a.tsv"), "-o", dir.file("p.val"), "--map-j2", "+1,0"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("J2 [-200.00,20.00] exceeded in"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("more"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(dir.file("a.tsv")), std::string::npos) << r.err;
  EXPECT_TRUE(test::ReadFile(dir.file("p.val")).empty());

  r = test::RunCli(
      {"plan", dir.file("a.tsv"), "-o", dir.file("p.val"), "--map-j2", "+1,0", "--clamp"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("J2 used [0.00, 20.00]"), std::string::npos) << r.out;

  r = test::RunCli({"plan", dir.file("a.tsv"), "-o", dir.file("q.val"), "--max-gap-s", "0.1"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("frames 205-208"), std::string::npos) << r.err;
}

TEST(CliPlan, UsageAndFileErrorsNameTheFlagOrFile) {
  test::TempDir dir;
  WriteRecording(dir.file("a.tsv"));
  const std::string in = dir.file("a.tsv"), out = dir.file("p.val");
  struct Case {
    std::vector<std::string> args;
    int code;
    const char* expect;
  } cases[] = {
      {{"plan", in}, 2, "-o/--output"},
      {{"plan", in, "-o", out, "--map-j2", "2,0"}, 2, "--map-j2"},
      {{"plan", in, "-o", out, "--cutoff", "20"}, 2, "--cutoff"},
      {{"plan", in, "-o", out, "--program-name", "A B"}, 2, "--program-name"},
      {{"plan", in, "-o", out, "--source", "hand"},
       2,
       "--source: 'hand' is not auto, arm or marker"},
      {{"plan", dir.file("missing.tsv"), "-o", out}, 1, "missing.tsv"},
      {{"plan", in, "-o", dir.file("no/such/dir/p.val")}, 1, "p.val"},
  };
  for (const Case& c : cases) {
    const auto r = test::RunCli(c.args);
    EXPECT_EQ(r.exit_code, c.code) << c.expect << ": " << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
  }
  test::WriteFile(dir.file("bad.profile"), "echo = yes\nspeed = 3\n");
  const auto r = test::RunCli({"plan", in, "-o", out, "--profile", dir.file("bad.profile")});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.profile:2: unknown key 'speed'"), std::string::npos) << r.err;
  EXPECT_TRUE(test::ReadFile(out).empty());
  const auto help = test::RunCli({"plan", "--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--cutoff HZ"), std::string::npos);
}

// A spreadsheet saves the angle file with a byte order mark and CRLF line ends: plan reads it
// as it reads the original, and send still recognises it as an angle file (not a VAL program).
TEST(CliPlan, AnAngleFileSavedWithAByteOrderMarkAndCrlfPlansTheSame) {
  test::TempDir dir;
  WriteRecording(dir.file("rec.tsv"));
  std::string crlf = "\xEF\xBB\xBF";
  for (char c : test::ReadFile(dir.file("rec.tsv")))
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  test::WriteFile(dir.file("saved.tsv"), crlf);
  test::CliResult a = test::RunCli({"-q", "plan", dir.file("rec.tsv"), "-o", dir.file("a.val")});
  test::CliResult b = test::RunCli({"-q", "plan", dir.file("saved.tsv"), "-o", dir.file("b.val")});
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  std::string va = test::ReadFile(dir.file("a.val")), vb = test::ReadFile(dir.file("b.val"));
  // The header names its source file; the program lines are the same.
  ASSERT_NE(va.find("rec.tsv"), std::string::npos);
  for (std::string* v : {&va, &vb}) {
    std::istringstream in(*v);
    std::string kept;
    for (std::string line; std::getline(in, line);) {
      if (line.find(".tsv") == std::string::npos) kept += line + "\n";
    }
    *v = kept;
  }
  EXPECT_EQ(va, vb);
  const test::CliResult dry = test::RunCli({"send", dir.file("saved.tsv"), "--dry-run"});
  EXPECT_EQ(dry.exit_code, 0) << dry.err;
  EXPECT_NE(dry.out.find("DO MOVE #PPOINT("), std::string::npos) << dry.out;
}

}  // namespace
}  // namespace armmimic
