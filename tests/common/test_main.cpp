// Shared GoogleTest main: fixes every PRNG seed so that test runs repeat exactly, and gives the
// process a temporary folder of its own. TMPDIR points there for the tests, the code they test
// and every program they start; what is still in it after the last test (shared folders removed)
// is litter: it is listed, removed, and fails the run.
#include <sys/stat.h>

#include <clocale>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "test_util.h"

namespace {

// A fresh folder under $TMPDIR (or /tmp) that becomes this process's TMPDIR; writable by all
// with the sticky bit, as /tmp is, for the tests that run the program as another user.
std::string MakeProcessTempDir() {
  const char* base = std::getenv("TMPDIR");
  std::string templ = std::string(base && *base ? base : "/tmp") + "/armmimic-tests-XXXXXX";
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  if (!mkdtemp(buf.data())) {
    std::cerr << "test_main: cannot make a temporary folder in " << templ << "\n";
    std::exit(1);
  }
  chmod(buf.data(), 01777);
  setenv("TMPDIR", buf.data(), 1);
  return buf.data();
}

// Lists what is left in `dir` (to stderr) and removes it; returns whether anything was left.
bool RemoveLitter(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<std::string> left;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    left.push_back(it->path().string());
  }
  for (const std::string& p : left) std::cerr << "test_main: left behind: " << p << "\n";
  fs::remove_all(dir, ec);
  return !left.empty();
}

}  // namespace

int main(int argc, char** argv) {
  std::srand(0x5eed);
  cv::theRNG().state = 0x5eed;
  cv::setNumThreads(1);
  const std::string tmp = MakeProcessTempDir();
  ::testing::InitGoogleTest(&argc, argv);
  int rc = RUN_ALL_TESTS();
  armmimic::test::RemoveSharedTempDirs();
  if (RemoveLitter(tmp)) {
    std::cerr << "test_main: the tests left files in their temporary folder (listed above); a "
                 "test must remove what it makes\n";
    if (rc == 0) rc = 1;
  }
  return rc;
}
