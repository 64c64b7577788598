// Text helpers (text.h): a piece of a file quoted in a message, and the escapes of the batch
// summary's fields.
#include "armmimic/core/text.h"

#include <sstream>

#include <gtest/gtest.h>

namespace armmimic {
namespace {

TEST(Excerpt, StaysOnOneLineAndCutsLongTextAtItsStart) {
  EXPECT_EQ(Excerpt("abc"), "abc");
  EXPECT_EQ(Excerpt("a\tb\nc\rd\x01"
                    "e"),
            "a\\tb\\nc\\rd\\x01e");
  EXPECT_EQ(Excerpt(std::string(100, 'x'), 10), std::string(10, 'x') + "... (100 characters)");
  // A UTF-8 character is never cut in two.
  const std::string u = std::string(9, 'x') + "\xC3\xBC" + std::string(10, 'y');
  EXPECT_EQ(Excerpt(u, 10), std::string(9, 'x') + "\xC3\xBC... (21 characters)");
}

TEST(TsvField, EscapesOnlyWhatWouldBreakALineOrAField) {
  EXPECT_EQ(EscapeTsvField("my take \xC3\xBC.avi"), "my take \xC3\xBC.avi");
  EXPECT_EQ(EscapeTsvField("a\tb\nc\rd\\e"), "a\\tb\\nc\\rd\\\\e");
  for (const std::string& name :
       {std::string("plain"), std::string("tab\there"), std::string("new\nline\r"),
        std::string("back\\slash\\t not a tab"), std::string("\\"), std::string("end\\")}) {
    const std::string field = EscapeTsvField(name);
    EXPECT_EQ(field.find_first_of("\t\n\r"), std::string::npos) << field;
    EXPECT_EQ(UnescapeTsvField(field), name) << field;
  }
  // A backslash before anything else is left as it is.
  EXPECT_EQ(UnescapeTsvField("a\\qb\\"), "a\\qb\\");
}

TEST(ReadTextLine, EndsALineAtLfCrlfOrACrAloneAndBoundsItsLength) {
  std::istringstream in("a\nbb\r\ncc\rd\r\n0123456789\nlast");
  std::string line;
  std::vector<std::string> lines;
  while (ReadTextLine(in, &line)) lines.push_back(line);
  EXPECT_EQ(lines, (std::vector<std::string>{"a", "bb", "cc", "d", "0123456789", "last"}));
  std::istringstream bounded("0123456789\nok\n");
  bool too_long = false;
  ASSERT_TRUE(ReadTextLine(bounded, &line, 4, &too_long));
  EXPECT_TRUE(too_long);
  EXPECT_EQ(line, "01234");  // the first max_length + 1 characters; the rest read past
  ASSERT_TRUE(ReadTextLine(bounded, &line, 4, &too_long));
  EXPECT_EQ(line, "ok");
  EXPECT_FALSE(ReadTextLine(bounded, &line));
}

}  // namespace
}  // namespace armmimic
