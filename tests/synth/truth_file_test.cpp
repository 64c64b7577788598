#include "armmimic/synth/truth_file.h"

#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "test_util.h"

namespace armmimic::synth {
namespace {

const char* kHeader =
    "frame\ttime_s\tupper_deg\tfore_deg\tyaw_deg\tbend_deg\tshoulder_x\tshoulder_y\telbow_x\t"
    "elbow_y\twrist_x\twrist_y";

Status Parse(const std::string& text, TruthFile* f) {
  std::istringstream in(text);
  return ParseTruthFile(in, "t.tsv", f);
}

std::string Row(const std::string& frame, const std::string& upper = "-90") {
  return frame + "\t0.5\t" + upper + "\t-80\t0\t10\t190\t100\t190\t144\t196.6\t181.4";
}

TEST(TruthFile, RoundTripKeepsValuesMetaAndExtraColumns) {
  TruthFile f;
  f.meta = {{"scene", "marker"}, {"note", "two words"}};
  f.extra_columns = {"file"};
  TruthRow a;
  a.frame = 3;
  a.time_s = 0.1;
  a.yaw_deg = 12.5;
  a.bend_deg = -30.25;
  a.extra = {"img_003.png"};
  TruthRow b;
  b.frame = 7;
  b.time_s = 0.2333;
  b.upper_deg = -90;
  b.fore_deg = 179.5;
  b.shoulder_x = 190.25;
  b.shoulder_y = 100;
  b.extra = {"img_007.png"};
  f.rows = {a, b};
  test::TempDir dir;
  const std::string path = dir.file("truth.tsv");
  ASSERT_TRUE(WriteTruthFile(path, f).ok());
  TruthFile g;
  const Status st = ReadTruthFile(path, &g);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(g.Meta("scene"), "marker");
  EXPECT_EQ(g.Meta("note"), "two words");
  ASSERT_EQ(g.extra_columns, std::vector<std::string>{"file"});
  EXPECT_EQ(g.ExtraColumn("file"), 0);
  ASSERT_EQ(g.rows.size(), 2u);
  EXPECT_EQ(g.rows[0].frame, 3);
  EXPECT_TRUE(std::isnan(g.rows[0].upper_deg));
  EXPECT_DOUBLE_EQ(g.rows[0].yaw_deg, 12.5);
  EXPECT_DOUBLE_EQ(g.rows[0].bend_deg, -30.25);
  EXPECT_EQ(g.rows[0].extra[0], "img_003.png");
  EXPECT_DOUBLE_EQ(g.rows[1].fore_deg, 179.5);
  EXPECT_DOUBLE_EQ(g.rows[1].shoulder_x, 190.25);
  EXPECT_TRUE(std::isnan(g.rows[1].yaw_deg));
  ASSERT_NE(g.Find(7), nullptr);
  EXPECT_EQ(g.Find(7)->extra[0], "img_007.png");
  EXPECT_EQ(g.Find(5), nullptr);
  EXPECT_TRUE(g.rows[0].HasAngles());
}

TEST(TruthFile, AcceptsCrlfCommentsAndTrailingColumns) {
  TruthFile f;
  const std::string text = std::string(kTruthFileMagic) + "\r\n# scene=arm seed=4\r\n# note\r\n" +
                           kHeader + "\tfile\textra2\r\n" + Row("0") + "\ta.png\tx\r\n" +
                           Row("1", "nan") + "\tb.png\ty\r\n\r\n";
  const Status st = Parse(text, &f);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(f.Meta("seed"), "4");
  EXPECT_EQ(f.extra_columns.size(), 2u);
  ASSERT_EQ(f.rows.size(), 2u);
  EXPECT_TRUE(std::isnan(f.rows[1].upper_deg));
  EXPECT_EQ(f.rows[1].extra[1], "y");
}

struct BadCase {
  const char* name;
  std::string text;
  std::string expect;  // substring of the message
};

TEST(TruthFile, RejectsMalformedFilesNamingTheLine) {
  const std::string m = std::string(kTruthFileMagic) + "\n";
  const std::string h = std::string(kHeader) + "\n";
  const std::vector<BadCase> cases = {
      {"empty", "", "t.tsv: empty file"},
      {"no magic", "# armmimic angles v1\n" + h, "t.tsv:1: not a truth file"},
      {"no header", m + "# only comments\n", "t.tsv: no header"},
      {"short header", m + "frame\ttime_s\n", "t.tsv:2: header has 2 columns"},
      {"renamed column",
       m + "frame\ttime_s\tupper\tfore_deg\tyaw_deg\tbend_deg\tshoulder_x\t"
           "shoulder_y\telbow_x\telbow_y\twrist_x\twrist_y\n",
       "t.tsv:2: header column 3 is 'upper', expected 'upper_deg'"},
      {"few fields", m + h + "0\t0\t-90\n", "t.tsv:3: row has 3 fields, the header has 12"},
      {"bad frame", m + h + Row("x1"), "t.tsv:3: frame 'x1'"},
      {"negative frame", m + h + Row("-1"), "t.tsv:3: frame '-1'"},
      {"bad number", m + h + Row("0", "abc"), "t.tsv:3: upper_deg 'abc' is not a number"},
      {"inf", m + h + Row("0", "inf"), "t.tsv:3: upper_deg 'inf'"},
      {"decimal comma", m + h + Row("0", "-90,5"), "t.tsv:3: upper_deg '-90,5'"},
      {"frames go back", m + h + Row("4") + "\n" + Row("4"), "t.tsv:4: frame 4 does not follow"},
      {"nan time", m + h + "0\tnan\t-90\t-80\t0\t10\t1\t1\t1\t1\t1\t1\n", "t.tsv:3: time_s"},
  };
  for (const BadCase& c : cases) {
    TruthFile f;
    const Status st = Parse(c.text, &f);
    EXPECT_FALSE(st.ok()) << c.name;
    EXPECT_NE(st.message().find(c.expect), std::string::npos)
        << c.name << ": got '" << st.message() << "'";
  }
}

TEST(TruthFile, MissingFileIsNamed) {
  TruthFile f;
  const Status st = ReadTruthFile("/nonexistent/truth.tsv", &f);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("/nonexistent/truth.tsv"), std::string::npos);
}

TEST(TruthFile, FormatRejectsRowsThatDoNotMatchTheExtraColumns) {
  TruthFile f;
  f.extra_columns = {"file"};
  f.rows.push_back(TruthRow());
  EXPECT_THROW(FormatTruthFile(f), std::invalid_argument);
}

TEST(TruthFile, ReadsAByteOrderMarkAndCrlfLineEnds) {
  const std::string text = "\xEF\xBB\xBF# armmimic truth v1\r\n# scene=arm seed=3\r\n" +
                           std::string(kHeader) + "\r\n" + Row("0") + "\r\n" + Row("1") + "\r\n";
  TruthFile f;
  const Status st = Parse(text, &f);
  ASSERT_TRUE(st.ok()) << st.message();
  ASSERT_EQ(f.rows.size(), 2u);
  EXPECT_DOUBLE_EQ(f.rows[1].wrist_y, 181.4);
  bool seed = false;
  for (const auto& [k, v] : f.meta) seed = seed || (k == "seed" && v == "3");
  EXPECT_TRUE(seed);
}

}  // namespace
}  // namespace armmimic::synth
