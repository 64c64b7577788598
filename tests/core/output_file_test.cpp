// The one output path: a regular file is replaced atomically, a symlink is written through, a
// character device or FIFO gets the bytes directly, a folder or socket is refused, and only the
// program's own stale temporaries are removed.
#include <fcntl.h>
#include <pty.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <future>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/output_file.h"
#include "test_util.h"

namespace armmimic {
namespace {

namespace fs = std::filesystem;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

bool IsLink(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode);
}

mode_t KindOf(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 ? (st.st_mode & S_IFMT) : 0;
}

std::vector<std::string> Entries(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(OutputFile, ANewOrRegularFileIsReplacedWholeKeepingItsMode) {
  test::TempDir dir;
  const std::string path = dir.file("a.tsv");
  ASSERT_TRUE(WriteOutputFile(path, "first\n").ok());
  EXPECT_EQ(test::ReadFile(path), "first\n");
  ASSERT_EQ(::chmod(path.c_str(), 0600), 0);
  struct stat before {};
  ASSERT_EQ(::stat(path.c_str(), &before), 0);
  ASSERT_TRUE(WriteOutputFile(path, "second\n").ok());
  struct stat after {};
  ASSERT_EQ(::stat(path.c_str(), &after), 0);
  EXPECT_EQ(test::ReadFile(path), "second\n");
  EXPECT_NE(before.st_ino, after.st_ino) << "replaced by a rename, not rewritten in place";
  EXPECT_EQ(after.st_mode & 07777, 0600u);
  EXPECT_EQ(Entries(dir.path()), std::vector<std::string>{"a.tsv"});
}

TEST(OutputFile, ASymlinkChainIsFollowedAndItsTargetReplacedInTheTargetsFolder) {
  test::TempDir dir;
  ASSERT_TRUE(fs::create_directory(dir.file("data")));
  const std::string target = dir.file("data/target.tsv");
  test::WriteFile(target, "old\n");
  // out.tsv -> hop.tsv -> data/target.tsv, the second link relative to its own folder.
  ASSERT_EQ(::symlink("data/target.tsv", dir.file("hop.tsv").c_str()), 0);
  ASSERT_EQ(::symlink(dir.file("hop.tsv").c_str(), dir.file("out.tsv").c_str()), 0);
  ASSERT_TRUE(WriteOutputFile(dir.file("out.tsv"), "new\n").ok());
  EXPECT_TRUE(IsLink(dir.file("out.tsv")));
  EXPECT_TRUE(IsLink(dir.file("hop.tsv")));
  EXPECT_EQ(KindOf(target), static_cast<mode_t>(S_IFREG));
  EXPECT_EQ(test::ReadFile(target), "new\n");
  EXPECT_EQ(Entries(dir.file("data")), std::vector<std::string>{"target.tsv"});
  // A link whose target does not exist yet: the target is created, the link kept.
  ASSERT_EQ(::symlink("data/later.tsv", dir.file("later.tsv").c_str()), 0);
  ASSERT_TRUE(WriteOutputFile(dir.file("later.tsv"), "made\n").ok());
  EXPECT_TRUE(IsLink(dir.file("later.tsv")));
  EXPECT_EQ(test::ReadFile(dir.file("data/later.tsv")), "made\n");
  // A loop is named, not followed for ever.
  ASSERT_EQ(::symlink("loop2", dir.file("loop1").c_str()), 0);
  ASSERT_EQ(::symlink("loop1", dir.file("loop2").c_str()), 0);
  const Status loop = WriteOutputFile(dir.file("loop1"), "x");
  ASSERT_FALSE(loop.ok());
  EXPECT_TRUE(Contains(loop.message(), "symbolic links")) << loop.message();
}

TEST(OutputFile, AFifoWithAReaderGetsTheBytesAndStaysAFifo) {
  test::TempDir dir;
  const std::string fifo = dir.file("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto reader = test::ReadFifoInBackground(fifo);
  std::string bytes;
  for (int i = 0; i < 5000; ++i) bytes += "row " + std::to_string(i) + "\n";  // > a pipe's buffer
  const Status st = WriteOutputFile(fifo, bytes);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(reader.get(), bytes);
  EXPECT_EQ(KindOf(fifo), static_cast<mode_t>(S_IFIFO));
  EXPECT_EQ(Entries(dir.path()), std::vector<std::string>{"pipe"});
}

// An angle file cut short cannot have its header rewritten in a FIFO: its last line marks it,
// and the reader takes that as complete=no.
TEST(OutputFile, AnAngleFileEndedEarlyInAFifoIsMarkedIncompleteByItsLastLine) {
  test::TempDir dir;
  const std::string fifo = dir.file("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto reader = test::ReadFifoInBackground(fifo);
  AngleFileWriter writer;
  ASSERT_TRUE(writer.Open(fifo, {{"engine", "lk"}}, false).ok());
  AngleRow row;
  row.frame = 7;
  row.status = RowStatus::kOk;
  row.upper_deg = -90;
  row.fore_deg = -80;
  ASSERT_TRUE(writer.Write(row).ok());
  ASSERT_TRUE(writer.Commit(false).ok());
  const std::string got = reader.get();
  EXPECT_TRUE(Contains(got, std::string("\n") + kIncompleteMark + "\n")) << got;
  AngleFile file;
  std::istringstream in(got);
  ASSERT_TRUE(ParseAngleFile(in, "pipe", &file).ok()) << got;
  EXPECT_FALSE(file.complete);
  ASSERT_EQ(file.rows.size(), 1u);
  EXPECT_EQ(file.rows[0].frame, 7);
}

TEST(OutputFile, AFifoNobodyReadsIsRefusedAfterAShortWait) {
  test::TempDir dir;
  const std::string fifo = dir.file("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  const Status st = WriteOutputFile(fifo, "x");
  const double waited =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_FALSE(st.ok());
  EXPECT_TRUE(Contains(st.message(), fifo + ": the FIFO has no reader")) << st.message();
  EXPECT_LT(waited, 30.0);
  EXPECT_EQ(KindOf(fifo), static_cast<mode_t>(S_IFIFO));
}

// Device nodes made with mknod in the temporary folder (the tests run as root): /dev/null's
// takes the bytes and stays a device; /dev/full's refuses them ("no space left"), which only a
// write into the device itself can meet. (A pseudo-terminal cannot be reached through a node
// outside /dev/pts, so the bytes' arrival is shown on a real terminal's own path, reached
// through a symlink in the temporary folder.)
TEST(OutputFile, ACharacterDeviceIsWrittenThroughNotReplaced) {
  test::TempDir dir;
  const std::string null_node = dir.file("x");
  const std::string full_node = dir.file("full");
  ASSERT_EQ(::mknod(null_node.c_str(), S_IFCHR | 0666, makedev(1, 3)), 0)
      << "mknod: " << std::strerror(errno) << " (the tests run as root)";
  ASSERT_EQ(::mknod(full_node.c_str(), S_IFCHR | 0666, makedev(1, 7)), 0) << std::strerror(errno);
  Status st = WriteOutputFile(null_node, std::string(100000, 'a'));
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(KindOf(null_node), static_cast<mode_t>(S_IFCHR));
  st = WriteOutputFile(full_node, "rows\n");
  ASSERT_FALSE(st.ok());
  EXPECT_TRUE(Contains(st.message(), full_node + ": write failed (no space left on the device)"))
      << st.message();
  EXPECT_EQ(KindOf(full_node), static_cast<mode_t>(S_IFCHR));

  int master = -1, slave = -1;
  char name[256] = {0};
  ASSERT_EQ(::openpty(&master, &slave, name, nullptr, nullptr), 0);
  termios raw{};
  ASSERT_EQ(::tcgetattr(slave, &raw), 0);
  ::cfmakeraw(&raw);
  ASSERT_EQ(::tcsetattr(slave, TCSANOW, &raw), 0);
  ASSERT_EQ(::symlink(name, dir.file("tty").c_str()), 0);
  st = WriteOutputFile(dir.file("tty"), "through the device\n");
  ASSERT_TRUE(st.ok()) << st.message();
  char buf[64] = {0};
  const ssize_t n = ::read(master, buf, sizeof buf);
  EXPECT_EQ(std::string(buf, n > 0 ? static_cast<std::size_t>(n) : 0), "through the device\n");
  EXPECT_EQ(KindOf(name), static_cast<mode_t>(S_IFCHR));
  EXPECT_EQ(KindOf(dir.file("tty")), static_cast<mode_t>(S_IFLNK));
  EXPECT_EQ(Entries(dir.path()), (std::vector<std::string>{"full", "tty", "x"}));
  ::close(slave);
  ::close(master);
}

TEST(OutputFile, AFolderASocketAndABlockDeviceAreRefusedByName) {
  test::TempDir dir;
  ASSERT_TRUE(fs::create_directory(dir.file("folder")));
  const std::string sock = dir.file("sock");
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::strncpy(addr.sun_path, sock.c_str(), sizeof addr.sun_path - 1);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  const std::string block = dir.file("block");
  ASSERT_EQ(::mknod(block.c_str(), S_IFBLK | 0600, makedev(7, 200)), 0) << std::strerror(errno);
  for (const auto& [path, words] :
       {std::pair<std::string, std::string>{dir.file("folder"), "is a folder"},
        {sock, "is a socket"},
        {block, "is a block device"}}) {
    const Status written = WriteOutputFile(path, "x");
    ASSERT_FALSE(written.ok()) << path;
    EXPECT_EQ(written.message(), path + ": " + words);
    const Status early = CheckOutputKinds({{"-o", path}});
    ASSERT_FALSE(early.ok()) << path;
    EXPECT_TRUE(Contains(early.message(), "-o " + path + ": " + words)) << early.message();
  }
  EXPECT_EQ(KindOf(sock), static_cast<mode_t>(S_IFSOCK));
  EXPECT_TRUE(CheckOutputKinds({{"-o", dir.file("new.tsv")}}).ok());
  ::close(fd);
}

TEST(OutputFile, OnlyTheProgramsOwnStaleTemporariesOfThatOutputAreRemoved) {
  test::TempDir dir;
  const std::string out = dir.file("a.tsv");
  const std::string prefix = OutputTempPrefix(out);
  EXPECT_EQ(prefix, ".a.tsv.armmimic-tmp.");
  const std::vector<std::string> kept = {
      ".a.tsv.armmimic-tmp.abc",       // too short for the pattern
      ".a.tsv.armmimic-tmp.abc12!",    // not letters and digits
      ".a.tsv.armmimic-tmp.abc123.x",  // a suffix that is not the target's extension
      ".a.tsv.backup1",                // the user's own file, six characters after the name
      ".b.tsv.armmimic-tmp.abc123",    // another output's temporary
      "a.tsv.armmimic-tmp.abc123",     // not hidden
  };
  for (const std::string& name : kept) test::WriteFile(dir.file(name), "keep");
  test::WriteFile(dir.file(prefix + "Zz9Qa1"), "");          // a killed run's
  test::WriteFile(dir.file(prefix + "XyZ789.tsv"), "rows");  // one with the extension
  // A temporary whose writer is alive (holds its lock) is not stale.
  const std::string busy = dir.file(prefix + "BUSY00");
  test::WriteFile(busy, "in progress");
  const int held = ::open(busy.c_str(), O_RDONLY);
  ASSERT_GE(held, 0);
  ASSERT_EQ(::flock(held, LOCK_EX), 0);

  ASSERT_TRUE(WriteOutputFile(out, "fresh\n").ok());
  std::vector<std::string> want = kept;
  want.push_back("a.tsv");
  want.push_back(prefix + "BUSY00");
  std::sort(want.begin(), want.end());
  EXPECT_EQ(Entries(dir.path()), want);
  ::close(held);
  EXPECT_EQ(RemoveStaleOutputTemps(out), 1);  // its writer is gone now
}

TEST(OutputFile, ALogIsWrittenInPlaceThroughALinkAndAppendsWhenAsked) {
  test::TempDir dir;
  test::WriteFile(dir.file("real.log"), "kept\n");
  ASSERT_EQ(::symlink("real.log", dir.file("link.log").c_str()), 0);
  std::FILE* f = nullptr;
  ASSERT_TRUE(OpenLogFile(dir.file("link.log"), true, &f).ok());
  std::fputs("added\n", f);
  EXPECT_TRUE(SyncOutput(f));
  std::fclose(f);
  EXPECT_TRUE(IsLink(dir.file("link.log")));
  EXPECT_EQ(test::ReadFile(dir.file("real.log")), "kept\nadded\n");
  const Status refused = OpenLogFile(dir.path(), false, &f);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.message(), dir.path() + ": is a folder");
}

TEST(OutputFile, InputErrorsSayWhatIsWrong) {
  test::TempDir dir;
  Status st = CheckInputFile(dir.path());
  ASSERT_FALSE(st.ok());
  EXPECT_TRUE(Contains(st.message(), dir.path() + ": is a folder")) << st.message();
  st = CheckInputFile(dir.file("none"));
  ASSERT_FALSE(st.ok());
  EXPECT_TRUE(Contains(st.message(), "not found")) << st.message();
  EXPECT_EQ(FileErrorText(EACCES), "permission denied");
}

}  // namespace
}  // namespace armmimic
