// No library message names a command-line flag: the library keys its errors by setting
// (Status::key()) and each shell words the setting its own way (the CLI as a flag, the GUI as a
// field). This scans every string literal of the library's sources for "--" followed by a
// letter; comments may still mention flags.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace armmimic {
namespace {

struct Literal {
  int line = 0;
  std::string text;
};

// The string literals of C++ source `src` (plain, prefixed and raw), with the line each starts
// on. Comments and character literals are skipped.
std::vector<Literal> StringLiterals(const std::string& src) {
  std::vector<Literal> out;
  int line = 1;
  std::size_t i = 0;
  const std::size_t n = src.size();
  auto advance = [&](std::size_t to) {
    for (; i < to && i < n; ++i) line += src[i] == '\n';
  };
  while (i < n) {
    const char c = src[i];
    if (c == '/' && i + 1 < n && src[i + 1] == '/') {
      const std::size_t end = src.find('\n', i);
      advance(end == std::string::npos ? n : end);
    } else if (c == '/' && i + 1 < n && src[i + 1] == '*') {
      const std::size_t end = src.find("*/", i + 2);
      advance(end == std::string::npos ? n : end + 2);
    } else if (c == 'R' && i + 1 < n && src[i + 1] == '"' &&
               (i == 0 || !std::isalnum(static_cast<unsigned char>(src[i - 1])) ||
                src[i - 1] == 'u' || src[i - 1] == 'U' || src[i - 1] == 'L' || src[i - 1] == '8')) {
      const std::size_t open = src.find('(', i + 2);
      if (open == std::string::npos) break;
      const std::string close = ")" + src.substr(i + 2, open - i - 2) + "\"";
      const std::size_t end = src.find(close, open + 1);
      const std::size_t stop = end == std::string::npos ? n : end;
      out.push_back({line, src.substr(open + 1, stop - open - 1)});
      advance(stop + close.size());
    } else if (c == '\'' && i > 0 && std::isxdigit(static_cast<unsigned char>(src[i - 1])) &&
               i + 1 < n && std::isxdigit(static_cast<unsigned char>(src[i + 1]))) {
      advance(i + 1);  // a digit separator (1'000), not a character literal
    } else if (c == '"' || c == '\'') {
      const int start_line = line;
      std::string text;
      std::size_t j = i + 1;
      while (j < n && src[j] != c && src[j] != '\n') {
        if (src[j] == '\\' && j + 1 < n) text += src[j++];
        text += src[j++];
      }
      if (c == '"') out.push_back({start_line, text});
      advance(j + 1);
    } else {
      advance(i + 1);
    }
  }
  return out;
}

// A flag of the source tree's own scripts ("scripts/deps.sh --with-model") belongs to that
// script's command line, not to a shell's, so a message may name it in full.
bool IsScriptFlag(const std::string& text, std::size_t at) {
  const std::size_t script = text.rfind("scripts/", at);
  if (script == std::string::npos) return false;
  const std::size_t sh = text.find(".sh ", script);
  return sh != std::string::npos && sh + 4 == at;
}

bool NamesAFlag(const std::string& text) {
  for (std::size_t k = 0; k + 2 < text.size(); ++k) {
    if (text[k] == '-' && text[k + 1] == '-' &&
        std::isalpha(static_cast<unsigned char>(text[k + 2])) && !IsScriptFlag(text, k)) {
      return true;
    }
  }
  return false;
}

TEST(LibraryMessagesTest, TheScannerFindsLiteralsAndSkipsComments) {
  const std::string src =
      "// a comment with \"--flag\"\n"
      "/* and \"--another\" */ int x = 1'000;\n"
      "auto a = \"fine\"; auto b = '\"';\n"
      "auto c = \"give \" \"--threshold\";\n"
      "auto d = R\"x(raw --raw)x\";\n";
  const std::vector<Literal> lits = StringLiterals(src);
  std::vector<std::string> flagged;
  for (const Literal& l : lits) {
    if (NamesAFlag(l.text)) flagged.push_back(std::to_string(l.line) + ":" + l.text);
  }
  ASSERT_EQ(flagged.size(), 2u);
  EXPECT_EQ(flagged[0], "4:--threshold");
  EXPECT_EQ(flagged[1], "5:raw --raw");
  EXPECT_FALSE(NamesAFlag("a -- b"));
  EXPECT_FALSE(NamesAFlag("fetch it with scripts/deps.sh --with-model"));
  EXPECT_TRUE(NamesAFlag("scripts/deps.sh fetches it; then give --model DIR"));
  EXPECT_FALSE(NamesAFlag("x--"));
}

// An option table's row names its flag as data (".Flag(\"--cutoff\")"): a literal that is a
// flag and nothing else, in a table's source, is that data, not a message.
bool IsTableFlag(const std::string& file_name, const std::string& text) {
  if (file_name.find("option_table") == std::string::npos &&
      file_name.find("port_table") == std::string::npos) {
    return false;
  }
  if (text.size() < 3 || text.compare(0, 2, "--") != 0) return false;
  for (std::size_t i = 2; i < text.size(); ++i) {
    const char c = text[i];
    if (!(std::islower(static_cast<unsigned char>(c)) ||
          std::isdigit(static_cast<unsigned char>(c)) || c == '-')) {
      return false;
    }
  }
  return true;
}

TEST(LibraryMessagesTest, TableFlagsAreDataOnlyInTables) {
  EXPECT_TRUE(IsTableFlag("option_tables.cpp", "--cutoff"));
  EXPECT_TRUE(IsTableFlag("port_table.cpp", "--data-bits"));
  EXPECT_FALSE(IsTableFlag("option_tables.cpp", "--cutoff: must be >= 0"));
  EXPECT_FALSE(IsTableFlag("planner.cpp", "--cutoff"));
}

TEST(LibraryMessagesTest, NoLibraryStringNamesACommandLineFlag) {
  namespace fs = std::filesystem;
  const fs::path root = ARMMIMIC_SOURCE_DIR;
  const char* layers[] = {"src/core", "src/engines", "src/robot", "src/synth",
                          "src/sim",  "src/serial",  "src/live",  "include"};
  int files = 0;
  std::vector<std::string> found;
  for (const char* layer : layers) {
    ASSERT_TRUE(fs::is_directory(root / layer)) << (root / layer);
    for (const auto& entry : fs::recursive_directory_iterator(root / layer)) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::stringstream buffer;
      buffer << in.rdbuf();
      ++files;
      for (const Literal& l : StringLiterals(buffer.str())) {
        if (NamesAFlag(l.text) && !IsTableFlag(entry.path().filename().string(), l.text)) {
          found.push_back(fs::relative(entry.path(), root).string() + ":" + std::to_string(l.line) +
                          ": \"" + l.text + "\"");
        }
      }
    }
  }
  EXPECT_GT(files, 100);  // the tree was found
  std::string list;
  for (const std::string& f : found) list += "  " + f + "\n";
  EXPECT_TRUE(found.empty())
      << "library strings name command-line flags; key the Status by its setting instead "
         "(Status::Error(\"analysis.start\", ...)):\n"
      << list;
}

}  // namespace
}  // namespace armmimic
