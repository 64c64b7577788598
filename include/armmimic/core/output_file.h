// The one output path every writer of armmimic uses (angle files, images, programs, summaries,
// journals, logs), so that whatever an output names, the program writes into it and never
// replaces what it should write through:
//
//   - a regular file, or a new one, is replaced atomically: the bytes go to a temporary beside
//     it, which is renamed over it when complete, so an interrupted run leaves the old file or
//     the new one (a log is the exception: it is written in place as it grows);
//   - a symlink is followed to its final target (chains too); the target is replaced in the
//     target's own folder and the link stays;
//   - a character device or a FIFO is written to directly, with no temporary file and no
//     truncation; a FIFO with no reader is waited for a few seconds, then refused;
//   - anything else (a folder, a socket, a block device) is refused. CheckOutputKinds() says so
//     before a command reads anything.
//
// The temporary is named ".<name>.armmimic-tmp.XXXXXX" beside the target <name>, where XXXXXX
// is six letters or digits (a video's temporary also ends in the target's extension, ".avi"), and
// its writer holds an flock on it while it writes. A run killed before its rename leaves that file
// behind; the next run to the same output removes every file of exactly that pattern whose lock is
// free (its writer is gone), and nothing else.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "armmimic/core/same_file.h"
#include "armmimic/core/status.h"

namespace armmimic {

// What an output path leads to.
enum class OutputKind {
  kFile,    // a regular file, or none yet: replaced atomically (or written in place as a log)
  kStream,  // a character device or a FIFO: written directly
};

struct OutputTarget {
  std::string path;      // as given
  std::string resolved;  // the final target after symlinks (kFile); `path` itself for kStream
  OutputKind kind = OutputKind::kFile;
  bool fifo = false;
};

// Where `path` leads and how it is written. Fails, naming `path`, for a folder ("is a folder"),
// a socket ("is a socket"), a block device, a symlink loop, a missing folder or a folder that
// may not be searched ("permission denied").
Status ResolveOutput(const std::string& path, OutputTarget* out);

// Fails when an output already is something no output may be (a folder, a socket, a block
// device, a symlink loop), with the role in the message ("-o x.tsv: is a folder"). The shells
// call it before they read any input and treat a failure as a usage error.
Status CheckOutputKinds(const std::vector<NamedPath>& outputs);

// The shells' early check of a command's outputs, before any input is read: CheckOutputKinds()
// and then CheckOutputsAreNotInputs() (same_file.h). A failure is a usage error.
Status CheckOutputs(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

// Fails, naming `path`, when an input file cannot be read: "is a folder", "permission denied",
// "not found".
Status CheckInputFile(const std::string& path);

// The words for a file error: "permission denied", "is a folder", "not found", ...
std::string FileErrorText(int err);

// The temporary-name prefix for the final target `resolved` (".<name>.armmimic-tmp.").
std::string OutputTempPrefix(const std::string& resolved);

// Removes the temporaries a killed run left beside `resolved` (see above); returns how many.
int RemoveStaleOutputTemps(const std::string& resolved);

class OutputFile {
 public:
  enum class Mode {
    kReplace,    // the whole file appears at Commit()
    kLog,        // a regular file is truncated and written in place, line by line
    kAppendLog,  // as kLog, appending to what is there
  };

  OutputFile() = default;
  ~OutputFile();  // Discard() unless Commit() was reached
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  Status Open(const std::string& path, Mode mode = Mode::kReplace);
  // For a writer that needs a file name rather than file() (a video encoder): a replacement
  // whose temporary, temp_path(), ends in the target's extension. Refuses a device or FIFO.
  Status OpenNamed(const std::string& path);
  std::FILE* file() { return file_; }
  const std::string& path() const { return target_.path; }
  // True when the bytes go to a temporary that Commit() renames (they can be read back from
  // temp_path() until then); false for a stream or a log.
  bool replacing() const { return !temp_path_.empty(); }
  const std::string& temp_path() const { return temp_path_; }
  // Flushes and closes; a replacement is fsynced and renamed over the target.
  Status Commit();
  // Closes; a temporary is removed and the target stays as it was.
  void Discard();

 private:
  friend Status OpenLogFile(const std::string& path, bool append, std::FILE** out);
  Status CreateTemp(const std::string& suffix);

  OutputTarget target_;
  std::string temp_path_;
  std::FILE* file_ = nullptr;
};

// A log (a journal, a latency or move log): opened through the rules above with Mode::kLog or
// kAppendLog, the FILE* handed to the caller, who fcloses it. Errors name `path`.
Status OpenLogFile(const std::string& path, bool append, std::FILE** out);

// fsync that is content with a device or FIFO (which has nothing to make durable).
bool SyncOutput(std::FILE* file);

// Writes `bytes` to `path` through OutputFile (atomically for a regular file).
Status WriteOutputFile(const std::string& path, const std::string& bytes);

}  // namespace armmimic
