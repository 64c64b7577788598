#include "armmimic/core/sha256.h"

#include <gtest/gtest.h>

#include <string>

#include "test_util.h"

namespace armmimic {
namespace {

std::string Hex(const std::string& s) {
  return Sha256Hex(reinterpret_cast<const std::uint8_t*>(s.data()), s.size());
}

// FIPS 180-4 examples, and a message that spans blocks.
TEST(Sha256, MatchesTheStandardsExamples) {
  EXPECT_EQ(Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(Hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, HashesAFileAndNamesAMissingOne) {
  test::TempDir dir;
  test::WriteFile(dir.file("f"), "abc");
  std::string hex;
  ASSERT_TRUE(Sha256File(dir.file("f"), &hex).ok());
  EXPECT_EQ(hex, Hex("abc"));
  const Status st = Sha256File(dir.file("none"), &hex);
  EXPECT_EQ(st.message(), dir.file("none") + ": cannot open (No such file or directory)");
}

}  // namespace
}  // namespace armmimic
