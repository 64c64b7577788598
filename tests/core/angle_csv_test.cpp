#include "armmimic/core/angle_csv.h"

#include <gtest/gtest.h>

#include "test_util.h"

namespace armmimic {
namespace {

AngleRow OkRow() {
  AngleRow r;
  r.frame = 12;
  r.time_s = 0.4;
  r.status = RowStatus::kOk;
  r.upper_deg = -90.5;
  r.fore_deg = 12.3456;
  r.yaw_deg = kNaN;  // a bent arm has no yaw
  r.bend_deg = 102.8456;
  r.upper_cx = 160.25;
  r.upper_cy = 100.5;
  r.fore_cx = 170;
  r.fore_cy = 80;
  return r;
}

TEST(AngleCsv, HeaderNamesEveryColumnWithItsUnit) {
  EXPECT_EQ(FormatCsvHeader(false, CsvStyle::kComma),
            "frame,time (s),status,upper (deg),fore (deg),yaw (deg),bend (deg),upper_cx (px),"
            "upper_cy (px),fore_cx (px),fore_cy (px)");
  EXPECT_EQ(FormatCsvHeader(true, CsvStyle::kSemicolon),
            "frame;time (s);status;upper (deg);fore (deg);yaw (deg);bend (deg);upper_cx (px);"
            "upper_cy (px);fore_cx (px);fore_cy (px);file;yaw signed (deg)");
}

TEST(AngleCsv, MissingValuesAreEmptyCells) {
  EXPECT_EQ(FormatCsvRow(OkRow(), false, CsvStyle::kComma),
            "12,0.4000,ok,-90.500,12.346,,102.846,160.25,100.50,170.00,80.00");
  AngleRow lost;
  lost.frame = 13;
  lost.time_s = 0.4333;
  lost.upper_cx = 5;  // a lost row's values are never written, whatever the struct holds
  EXPECT_EQ(FormatCsvRow(lost, false, CsvStyle::kComma), "13,0.4333,lost,,,,,,,,");
}

TEST(AngleCsv, SemicolonStyleWritesDecimalCommas) {
  EXPECT_EQ(FormatCsvRow(OkRow(), false, CsvStyle::kSemicolon),
            "12;0,4000;ok;-90,500;12,346;;102,846;160,25;100,50;170,00;80,00");
}

TEST(AngleCsv, FileNamesAreQuotedOnlyWhenNeeded) {
  AngleRow r = OkRow();
  r.file = "view 1.png";
  EXPECT_EQ(FormatCsvRow(r, true, CsvStyle::kComma),
            "12,0.4000,ok,-90.500,12.346,,102.846,160.25,100.50,170.00,80.00,view 1.png,");
  r.yaw_signed_deg = -23.4567;  // the marker engine's signed yaw follows the file
  EXPECT_EQ(FormatCsvRow(r, true, CsvStyle::kSemicolon),
            "12;0,4000;ok;-90,500;12,346;;102,846;160,25;100,50;170,00;80,00;view 1.png;-23,457");
  r.file = "a,b\"c.png";
  const std::string comma = FormatCsvRow(r, true, CsvStyle::kComma);
  EXPECT_EQ(comma.substr(comma.rfind(",\"") + 1), "\"a,b\"\"c.png\",-23.457");
  // With ';' as separator a comma in a name needs no quotes, but the quote still does.
  const std::string semi = FormatCsvRow(r, true, CsvStyle::kSemicolon);
  EXPECT_EQ(semi.substr(semi.rfind(";\"") + 1), "\"a,b\"\"c.png\";-23,457");
}

TEST(AngleCsv, FileFromTheCliHasOneLinePerRowAndTheSameValues) {
  test::TempDir dir;
  const std::string tsv = dir.file("angles.tsv");
  const std::string csv = dir.file("angles.csv");
  test::WriteFile(tsv,
                  "# armmimic angles v1\n# engine=bgsub\n"
                  "frame\ttime_s\tstatus\tupper_deg\tfore_deg\tyaw_deg\tbend_deg\tupper_cx\t"
                  "upper_cy\tfore_cx\tfore_cy\n"
                  "60\t2.0000\tok\t-80.000\t-60.000\tnan\t20.000\t150.00\t90.00\t160.00\t120.00\n"
                  "61\t2.0333\tlost\tnan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n");
  AngleFile f;
  ASSERT_TRUE(ReadAngleFile(tsv, &f).ok());
  ASSERT_TRUE(WriteAnglesCsv(csv, f.rows, f.has_file_column, CsvStyle::kComma).ok());
  EXPECT_EQ(test::ReadFile(csv), FormatCsvHeader(false, CsvStyle::kComma) +
                                     "\r\n60,2.0000,ok,-80.000,-60.000,,20.000,150.00,90.00,"
                                     "160.00,120.00\r\n61,2.0333,lost,,,,,,,,\r\n");
}

TEST(AngleCsv, AnUnwritableTargetIsNamed) {
  const Status st =
      WriteAnglesCsv("/nonexistent-folder/angles.csv", {OkRow()}, false, CsvStyle::kComma);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("/nonexistent-folder/angles.csv"), std::string::npos) << st.message();
}

}  // namespace
}  // namespace armmimic
