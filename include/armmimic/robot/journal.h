// SendJournal: the append-only record of a stream beside its program (PROGRAM.val.journal), so
// `send --resume` continues after the last acknowledged line: no move lost, none repeated.
//
//   # armmimic send journal v1
//   program sha=<16 hex digits> lines=<count> source=<file name>
//   sent 3 12          <- line 3 of the stream (file line 12) is being written
//   ack 3 12           <- ... and the controller acknowledged it
//   ack 3 12 where     <- acknowledged later, after WHERE showed it had run
//   done
//
// Every record is flushed and fsync'd before the protocol goes on.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "armmimic/core/status.h"

namespace armmimic::robot {

struct JournalState {
  bool exists = false;
  std::string hash;
  int lines = 0;         // lines in the stream when the journal was started
  int acknowledged = 0;  // highest stream index (1-based) acknowledged; 0: none
  int sent = 0;          // highest stream index written
  int sent_line_no = 0;  // its file line
  bool done = false;
  // Written but never acknowledged: the link died before the controller's prompt came back.
  bool uncertain() const { return sent > acknowledged; }
};

class SendJournal {
 public:
  SendJournal() = default;
  ~SendJournal();
  SendJournal(const SendJournal&) = delete;
  SendJournal& operator=(const SendJournal&) = delete;

  static std::string PathFor(const std::string& program_path) { return program_path + ".journal"; }
  // FNV-1a 64 of the lines and their order, as 16 hex digits: the stream's identity.
  static std::string Hash(const std::vector<std::string>& lines);
  // Reads a journal; a missing file gives exists=false and ok. Malformed lines are errors naming
  // "file:line".
  static Status Read(const std::string& path, JournalState* state);

  // Starts a new journal (replacing an old one) or, with `append`, continues an existing one.
  Status Open(const std::string& path, const std::string& hash, int lines,
              const std::string& source_name, bool append);
  // index is 1-based in the stream; line_no is the file line.
  Status Sent(int index, int line_no);
  Status Acked(int index, int line_no, const std::string& note = "");
  Status Done();
  void Close();
  const std::string& path() const { return path_; }

 private:
  Status Append(const std::string& record);
  std::string path_;
  std::FILE* file_ = nullptr;
};

}  // namespace armmimic::robot
