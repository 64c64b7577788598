// The angle file's reader and writer: round trips of every column (the optional confidence,
// marker and 3-D columns too), locales, line ends and the messages for malformed files.
// Length: one test per rule of the one format; splitting it would split the format's tests.
#include "armmimic/core/angle_file.h"

#include <clocale>
#include <sstream>

#include <gtest/gtest.h>

#include "test_util.h"

namespace armmimic {
namespace {

const char* kHeader =
    "frame\ttime_s\tstatus\tupper_deg\tfore_deg\tyaw_deg\tbend_deg\tupper_cx\tupper_cy\tfore_"
    "cx\tfore_cy";

Status Parse(const std::string& text, AngleFile* f) {
  std::istringstream in(text);
  return ParseAngleFile(in, "a.tsv", f);
}

TEST(AngleFile, RoundTripKeepsEveryValue) {
  test::TempDir dir;
  const std::string path = dir.file("angles.tsv");
  AngleFileWriter w;
  ASSERT_TRUE(
      w.Open(path, {{"engine", "bgsub"}, {"source", "my scene.avi"}, {"fps", "30"}}, false).ok());
  AngleRow r1;
  r1.frame = 105;
  r1.time_s = 3.5;
  r1.status = RowStatus::kOk;
  r1.upper_deg = -90;
  r1.fore_deg = 12.3456;
  r1.yaw_deg = kNaN;
  r1.bend_deg = 102.3456;
  r1.upper_cx = 160.25;
  r1.upper_cy = 100.5;
  r1.fore_cx = 170;
  r1.fore_cy = 80;
  AngleRow r2;
  r2.frame = 106;
  r2.time_s = 3.5333;
  ASSERT_TRUE(w.Write(r1).ok());
  ASSERT_TRUE(w.Write(r2).ok());
  ASSERT_TRUE(w.Commit().ok());

  const std::string text = test::ReadFile(path);
  EXPECT_EQ(text.rfind("# armmimic angles v1\n# engine=bgsub source=my%20scene.avi fps=30\n", 0),
            0u);
  EXPECT_NE(text.find(std::string(kHeader) + "\n"), std::string::npos);

  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(path, &f).ok());
  EXPECT_EQ(f.Meta("source"), "my scene.avi");
  EXPECT_TRUE(f.complete);
  ASSERT_EQ(f.rows.size(), 2u);
  EXPECT_EQ(f.rows[0].frame, 105);
  EXPECT_TRUE(f.rows[0].ok());
  EXPECT_DOUBLE_EQ(f.rows[0].upper_deg, -90);
  EXPECT_NEAR(f.rows[0].fore_deg, 12.346, 1e-9);
  EXPECT_TRUE(std::isnan(f.rows[0].yaw_deg));
  EXPECT_DOUBLE_EQ(f.rows[0].upper_cx, 160.25);
  EXPECT_FALSE(f.rows[1].ok());
  EXPECT_TRUE(std::isnan(f.rows[1].upper_deg));
}

TEST(AngleFile, WritesDotDecimalsUnderACommaLocale) {
  test::TempDir dir;
  const std::string path = dir.file("angles.tsv");
  std::string written;
  AngleFile back;
  Status read;
  {
    const test::CommaDecimalLocale comma;
    ASSERT_TRUE(comma.active()) << comma.c_error();
    EXPECT_EQ(FormatNumber(-12.5, 3), "-12.500");
    AngleFileWriter w;
    ASSERT_TRUE(w.Open(path, {{"engine", "lk"}, {"fps", "29.97"}}, false).ok());
    AngleRow r;
    r.frame = 7;
    r.time_s = 0.2336;
    r.status = RowStatus::kOk;
    r.upper_deg = -12.5;
    r.fore_deg = 1234.5 / 10;
    r.upper_cx = 1234.25;
    ASSERT_TRUE(w.Write(r).ok());
    ASSERT_TRUE(w.Commit().ok());
    written = test::ReadFile(path);
    read = ReadAngleFile(path, &back);
  }
  EXPECT_NE(written.find("7\t0.2336\tok\t-12.500\t123.450\tnan\tnan\t1234.25\t"), std::string::npos)
      << written;
  ASSERT_TRUE(read.ok()) << read.message();
  ASSERT_EQ(back.rows.size(), 1u);
  EXPECT_DOUBLE_EQ(back.rows[0].upper_deg, -12.5);
  EXPECT_DOUBLE_EQ(back.rows[0].upper_cx, 1234.25);
}

TEST(AngleFile, FormatNumberNeverWritesNegativeZero) {
  EXPECT_EQ(FormatNumber(-0.0001, 3), "0.000");
  EXPECT_EQ(FormatNumber(kNaN, 3), "nan");
}

TEST(AngleFile, MarkerFileColumnRoundTrips) {
  std::string text = "# armmimic angles v1\n" + std::string(kHeader) + "\tfile\n" +
                     "0\t0.0000\tok\tnan\tnan\t12.000\t-3.000\tnan\tnan\tnan\tnan\timg_000.png\n";
  AngleFile f;
  ASSERT_TRUE(Parse(text, &f).ok());
  ASSERT_TRUE(f.has_file_column);
  EXPECT_EQ(f.rows[0].file, "img_000.png");
  EXPECT_DOUBLE_EQ(f.rows[0].yaw_deg, 12);
}

TEST(AngleFile, MarkerSignedYawRoundTripsAndIsFoundByName) {
  test::TempDir dir;
  const std::string path = dir.file("m.tsv");
  AngleFileWriter w;
  ASSERT_TRUE(w.Open(path, {{"engine", "marker"}}, true, false, true).ok());
  AngleRow r;
  r.status = RowStatus::kOk;
  r.yaw_deg = 12.5;
  r.yaw_signed_deg = -12.5;
  r.bend_deg = 3;
  r.file = "img_000.png";
  ASSERT_TRUE(w.Write(r).ok());
  AngleRow lost;
  lost.frame = 1;
  lost.file = "img_001.png";
  ASSERT_TRUE(w.Write(lost).ok());
  ASSERT_TRUE(w.Commit().ok());
  EXPECT_NE(test::ReadFile(path).find("\tfile\tyaw_signed_deg\n"), std::string::npos);
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(path, &f).ok());
  ASSERT_TRUE(f.has_file_column && f.has_signed_yaw_column);
  EXPECT_DOUBLE_EQ(f.rows[0].yaw_signed_deg, -12.5);
  EXPECT_DOUBLE_EQ(f.rows[0].turn_yaw_deg(), -12.5);
  EXPECT_TRUE(std::isnan(f.rows[1].yaw_signed_deg));
  // Found by name among other trailing columns, in any order; without it the yaw is yaw_deg.
  const std::string text = std::string(kHeader) + "\tconfidence\tyaw_signed_deg\tfile\n" +
                           "0\t0\tok\tnan\tnan\t7\t1\tnan\tnan\tnan\tnan\t0.9\t7\ta.png\n";
  ASSERT_TRUE(Parse(text, &f).ok()) << Parse(text, &f).message();
  EXPECT_DOUBLE_EQ(f.rows[0].yaw_signed_deg, 7);
  const std::string plain =
      std::string(kHeader) + "\n0\t0\tok\tnan\tnan\t7\t1\tnan\tnan\tnan\tnan\n";
  ASSERT_TRUE(Parse(plain, &f).ok());
  EXPECT_FALSE(f.has_signed_yaw_column);
  EXPECT_DOUBLE_EQ(f.rows[0].turn_yaw_deg(), 7);
}

TEST(AngleFile, UnknownTrailingColumnsAreIgnored) {
  std::string text =
      std::string(kHeader) + "\textra\n" + "3\t0.1\tok\t1\t2\t3\t1\t4\t5\t6\t7\twhatever\n";
  AngleFile f;
  ASSERT_TRUE(Parse(text, &f).ok()) << Parse(text, &f).message();
  EXPECT_EQ(f.rows.size(), 1u);
  EXPECT_FALSE(f.has_file_column);
}

TEST(AngleFile, ConfidenceColumnRoundTrips) {
  test::TempDir dir;
  AngleFileWriter w;
  ASSERT_TRUE(w.Open(dir.file("a.tsv"), {{"engine", "pose"}}, false, true).ok());
  AngleRow ok;
  ok.frame = 0;
  ok.status = RowStatus::kOk;
  ok.upper_deg = -90;
  ok.fore_deg = -45;
  ok.confidence = 0.8126;
  AngleRow lost;
  lost.frame = 1;
  lost.confidence = 0.125;
  ASSERT_TRUE(w.Write(ok).ok());
  ASSERT_TRUE(w.Write(lost).ok());
  ASSERT_TRUE(w.Commit().ok());
  EXPECT_NE(test::ReadFile(dir.file("a.tsv")).find("\tfore_cy\tconfidence\n"), std::string::npos);
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(dir.file("a.tsv"), &f).ok());
  ASSERT_TRUE(f.has_confidence_column);
  ASSERT_EQ(f.rows.size(), 2u);
  EXPECT_DOUBLE_EQ(f.rows[0].confidence, 0.813);  // three decimals
  EXPECT_DOUBLE_EQ(f.rows[1].confidence, 0.125);  // lost rows keep theirs
  // A confidence outside 0..1 is refused, naming the line.
  const std::string bad =
      std::string(kHeader) + "\tconfidence\n" + "0\t0\tok\t1\t2\tnan\t1\t4\t5\t6\t7\t1.5\n";
  const Status st = Parse(bad, &f);
  EXPECT_EQ(st.message(), "a.tsv:2: confidence \"1.5\" is not a number in [0, 1] (or nan)");
}

TEST(AngleFile, The3dColumnsRoundTripLastAndOnlyInOkRows) {
  test::TempDir dir;
  AngleFileWriter w;
  ASSERT_TRUE(w.Open(dir.file("a.tsv"), {{"engine", "pose"}}, false, true, false, true).ok());
  AngleRow ok;
  ok.status = RowStatus::kOk;
  ok.upper_deg = -100;
  ok.upper_az_deg = 180;
  ok.upper_el_deg = -65.25;
  ok.fore_az_deg = 90;
  ok.fore_el_deg = 0;
  ok.elbow_deg = 157.5;
  AngleRow lost = ok;  // a lost row's angles are written as nan whatever they hold
  lost.frame = 1;
  lost.status = RowStatus::kLost;
  ASSERT_TRUE(w.Write(ok).ok());
  ASSERT_TRUE(w.Write(lost).ok());
  ASSERT_TRUE(w.Commit().ok());
  const std::string text = test::ReadFile(dir.file("a.tsv"));
  EXPECT_NE(text.find("\tconfidence\tupper_az_deg\tupper_el_deg\tfore_az_deg\tfore_el_deg\t"
                      "elbow_deg\n"),
            std::string::npos);
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(dir.file("a.tsv"), &f).ok());
  ASSERT_TRUE(f.has_3d_columns);
  ASSERT_EQ(f.rows.size(), 2u);
  EXPECT_DOUBLE_EQ(f.rows[0].upper_az_deg, 180);
  EXPECT_DOUBLE_EQ(f.rows[0].upper_el_deg, -65.25);
  EXPECT_DOUBLE_EQ(f.rows[0].fore_az_deg, 90);
  EXPECT_DOUBLE_EQ(f.rows[0].elbow_deg, 157.5);
  EXPECT_TRUE(std::isnan(f.rows[1].upper_az_deg));
  EXPECT_TRUE(std::isnan(f.rows[1].elbow_deg));
}

TEST(AngleFile, The3dColumnsAreReadByNameAndAFileWithoutThemReadsAsBefore) {
  AngleFile f;
  const std::string some = std::string(kHeader) + "\telbow_deg\textra\tupper_el_deg\n" +
                           "0\t0\tok\t1\t2\tnan\t1\t4\t5\t6\t7\t90\tx\t-30\n";
  ASSERT_TRUE(Parse(some, &f).ok()) << Parse(some, &f).message();
  EXPECT_TRUE(f.has_3d_columns);
  EXPECT_DOUBLE_EQ(f.rows[0].elbow_deg, 90);
  EXPECT_DOUBLE_EQ(f.rows[0].upper_el_deg, -30);
  EXPECT_TRUE(std::isnan(f.rows[0].upper_az_deg));  // a column the file does not have
  const std::string plain = std::string(kHeader) + "\n0\t0\tok\t1\t2\tnan\t1\t4\t5\t6\t7\n";
  ASSERT_TRUE(Parse(plain, &f).ok());
  EXPECT_FALSE(f.has_3d_columns);
  EXPECT_DOUBLE_EQ(f.rows[0].upper_deg, 1);
  EXPECT_TRUE(std::isnan(f.rows[0].elbow_deg));
}

TEST(AngleFile, A3dValueOutsideItsRangeOrInALostRowNamesTheLine) {
  const std::string head =
      std::string(kHeader) + "\tupper_az_deg\tupper_el_deg\tfore_az_deg\tfore_el_deg\telbow_deg\n";
  const std::string ok = "0\t0\tok\t1\t2\tnan\t1\t4\t5\t6\t7\t";
  const std::string lost = "0\t0\tlost\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\t";
  const std::pair<std::string, std::string> cases[] = {
      {ok + "-180.5\t0\t0\t0\t90\n", "a.tsv:2: upper_az_deg -180.5 is outside (-180, 180]"},
      {ok + "0\t91\t0\t0\t90\n", "a.tsv:2: upper_el_deg 91 is outside [-90, 90]"},
      {ok + "0\t0\t0\t0\t-1\n", "a.tsv:2: elbow_deg -1 is outside [0, 180]"},
      {ok + "0\t0\tleft\t0\t90\n",
       "a.tsv:2: fore_az_deg \"left\" is not a number (use '.' decimals, or nan)"},
      {lost + "nan\tnan\tnan\t5\tnan\n",
       "a.tsv:2: status is lost but fore_el_deg is a number (lost rows carry nan angles)"},
  };
  for (const auto& [body, expect] : cases) {
    AngleFile f;
    EXPECT_EQ(Parse(head + body, &f).message(), expect) << body;
  }
  AngleFile f;
  EXPECT_TRUE(Parse(head + ok + "180\t-90\t-179.5\t90\t0\n", &f).ok());  // the bounds
}

struct BadCase {
  const char* name;
  std::string body;
  const char* expect;  // substring of the message
};

TEST(AngleFile, MalformedFilesNameTheLine) {
  const std::string h = std::string("# armmimic angles v1\n") + kHeader + "\n";
  const std::string signed_h =
      std::string("# armmimic angles v1\n") + kHeader + "\tyaw_signed_deg\n";
  const std::vector<BadCase> cases = {
      {"bad number", h + "0\t0\tok\t1,5\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n",
       "a.tsv:3: upper_deg \"1,5\""},
      {"wrong header", "# armmimic angles v1\nframe\ttime\tstatus\n", "a.tsv:2: bad column header"},
      {"short row", h + "0\t0\tok\t1\n", "a.tsv:3: row has 4 fields"},
      {"huge line", h + std::string(70000, '1') + "\n", "a.tsv:3: line is longer"},
      {"bad status", h + "0\t0\tmaybe\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n",
       "a.tsv:3: status"},
      {"inf", h + "0\t0\tok\tinf\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n", "a.tsv:3: upper_deg"},
      {"nan time", h + "0\tnan\tok\t1\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n", "a.tsv:3: time_s"},
      {"duplicate frame",
       h + "4\t0\tlost\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n" +
           "4\t0\tlost\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n",
       "a.tsv:4: frame 4 is repeated"},
      {"out of order",
       h + "4\t0\tlost\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n" +
           "2\t0\tlost\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n",
       "a.tsv:4: frame 2 is out of order"},
      {"lost with angle", h + "0\t0\tlost\t5\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n",
       "a.tsv:3: status is lost"},
      {"negative frame", h + "-1\t0\tlost\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n",
       "a.tsv:3: frame"},
      {"out of range", h + "0\t0\tok\t270\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n",
       "a.tsv:3: upper_deg 270"},
      {"negative yaw", h + "0\t0\tok\tnan\tnan\t-3\tnan\tnan\tnan\tnan\tnan\n", "a.tsv:3: yaw_deg"},
      {"version 2", "# armmimic angles v2\n" + std::string(kHeader) + "\n", "a.tsv:1: unsupported"},
      {"signed yaw not a number", signed_h + "0\t0\tok\tnan\tnan\t3\tnan\tnan\tnan\tnan\tnan\tx\n",
       "a.tsv:3: yaw_signed_deg \"x\""},
      {"signed yaw on a lost row",
       signed_h + "0\t0\tlost\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\t3\n",
       "a.tsv:3: status is lost but yaw_signed_deg"},
      {"signed yaw out of range",
       signed_h + "0\t0\tok\tnan\tnan\t3\tnan\tnan\tnan\tnan\tnan\t-200\n",
       "a.tsv:3: yaw_signed_deg -200 is outside"},
      {"empty", "", "a.tsv: no column header"},
  };
  for (const auto& c : cases) {
    AngleFile f;
    const Status st = Parse(c.body, &f);
    EXPECT_FALSE(st.ok()) << c.name;
    EXPECT_NE(st.message().find(c.expect), std::string::npos) << c.name << ": " << st.message();
  }
}

TEST(AngleFile, MissingFileNamesThePath) {
  AngleFile f;
  const Status st = ReadAngleFile("/nonexistent/x.tsv", &f);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("/nonexistent/x.tsv"), std::string::npos);
}

TEST(AngleFile, WriterLeavesTargetUntouchedUntilCommit) {
  test::TempDir dir;
  const std::string path = dir.file("a.tsv");
  test::WriteFile(path, "previous");
  {
    AngleFileWriter w;
    ASSERT_TRUE(w.Open(path, {{"engine", "lk"}}, false).ok());
    AngleRow r;
    ASSERT_TRUE(w.Write(r).ok());
    EXPECT_EQ(test::ReadFile(path), "previous");
  }  // destroyed without Commit
  EXPECT_EQ(test::ReadFile(path), "previous");
}

TEST(AngleFile, IncompleteCommitKeepsRowsAndMarksHeader) {
  test::TempDir dir;
  const std::string path = dir.file("a.tsv");
  AngleFileWriter w;
  ASSERT_TRUE(w.Open(path, {{"engine", "lk"}}, false).ok());
  for (int i = 0; i < 3; ++i) {
    AngleRow r;
    r.frame = i;
    ASSERT_TRUE(w.Write(r).ok());
  }
  ASSERT_TRUE(w.Commit(false).ok());
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(path, &f).ok());
  EXPECT_FALSE(f.complete);
  EXPECT_EQ(f.rows.size(), 3u);
}

TEST(AngleFile, WriterNamesMissingDirectory) {
  AngleFileWriter w;
  const Status st = w.Open("/nonexistent-dir/a.tsv", {}, false);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("/nonexistent-dir"), std::string::npos);
}

// A spreadsheet saves with a UTF-8 byte order mark and CRLF line ends: both are read.
TEST(AngleFile, ReadsAByteOrderMarkAndCrlfLineEnds) {
  const std::string text = "\xEF\xBB\xBF# armmimic angles v1\r\n# engine=lk source=v.avi\r\n" +
                           std::string(kHeader) + "\r\n" +
                           "3\t0.1\tok\t1\t2\t3\t1\t4\t5\t6\t7\r\n" +
                           "4\t0.2\tlost\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\r\n";
  AngleFile f;
  const Status st = Parse(text, &f);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(f.Meta("engine"), "lk");
  EXPECT_EQ(f.Meta("source"), "v.avi");
  ASSERT_EQ(f.rows.size(), 2u);
  EXPECT_DOUBLE_EQ(f.rows[0].fore_cy, 7);
  EXPECT_FALSE(f.rows[1].ok());
  // A file without the magic line may start with the header itself, after the mark.
  ASSERT_TRUE(
      Parse("\xEF\xBB\xBF" + std::string(kHeader) + "\n3\t0.1\tok\t1\t2\t3\t1\t4\t5\t6\t7\n", &f)
          .ok());
  // Only at the start of the file: elsewhere the bytes are an error that names the line.
  const Status late = Parse(std::string(kHeader) +
                                "\n\xEF\xBB\xBF"
                                "3\t0.1\tok\t1\t2\t3\t1\t4\t5\t6\t7\n",
                            &f);
  ASSERT_FALSE(late.ok());
  EXPECT_NE(late.message().find("a.tsv:2:"), std::string::npos) << late.message();
}

// An old Mac editor ends lines with a CR alone: read as LF, with the same line numbers.
TEST(AngleFile, ReadsCrOnlyLineEnds) {
  const std::string text = "# armmimic angles v1\r# engine=lk source=v.avi\r" +
                           std::string(kHeader) + "\r" + "3\t0.1\tok\t1\t2\t3\t1\t4\t5\t6\t7\r" +
                           "4\t0.2\tlost\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\r";
  AngleFile f;
  Status st = Parse(text, &f);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(f.Meta("engine"), "lk");
  EXPECT_EQ(f.meta_line, 2);
  ASSERT_EQ(f.rows.size(), 2u);
  EXPECT_FALSE(f.rows[1].ok());
  st = Parse(text + "5\t0.3\tmaybe\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\r", &f);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message().rfind("a.tsv:6: status \"maybe\"", 0), 0u) << st.message();
}

// A message quotes at most the start of one line, whatever the file holds.
TEST(AngleFile, MessagesQuoteOneShortPieceOfTheFile) {
  AngleFile f;
  const std::string huge(50000, 'q');
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"# armmimic angles v7 " + huge + "\n", "a.tsv:1: unsupported angle file version"},
      {huge + "\tx\n", "a.tsv:1: bad column header: column 1 is \"qqq"},
      {std::string(kHeader) + "\n" + huge + "\t0.1\tok\t1\t2\t3\t1\t4\t5\t6\t7\n",
       "a.tsv:2: frame \"qqq"},
      {std::string(kHeader) + "\n3\t0.1\tok\t1\t2\t3\t1\t4\t5\t6\t" + huge + "\n",
       "a.tsv:2: fore_cy \"qqq"},
  };
  for (const auto& [text, says] : cases) {
    const Status st = Parse(text, &f);
    ASSERT_FALSE(st.ok()) << says;
    EXPECT_EQ(st.message().rfind(says, 0), 0u) << st.message().substr(0, 200);
    EXPECT_LT(st.message().size(), 300u) << st.message().substr(0, 300);
    EXPECT_NE(st.message().find(" characters)"), std::string::npos) << st.message();
  }
}

}  // namespace
}  // namespace armmimic
