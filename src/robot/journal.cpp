#include "armmimic/robot/journal.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "armmimic/core/output_file.h"

namespace armmimic::robot {
namespace {

constexpr const char* kJournalMagic = "# armmimic send journal v1";

bool ParseNonNegative(const std::string& text, int* out) {
  if (text.empty() || text.size() > 9) return false;
  int v = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + (c - '0');
  }
  *out = v;
  return true;
}

}  // namespace

SendJournal::~SendJournal() { Close(); }

std::string SendJournal::Hash(const std::vector<std::string>& lines) {
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](unsigned char c) {
    h ^= c;
    h *= 1099511628211ULL;
  };
  for (const std::string& line : lines) {
    for (char c : line) mix(static_cast<unsigned char>(c));
    mix('\n');
  }
  char buf[17];
  std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

Status SendJournal::Read(const std::string& path, JournalState* state) {
  *state = JournalState();
  std::ifstream in(path);
  if (!in) {
    if (access(path.c_str(), F_OK) != 0) return Status::Ok();
    return Status::Error(path + ": cannot read the journal");
  }
  state->exists = true;
  std::string line;
  int line_no = 0;
  bool have_program = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string where = path + ":" + std::to_string(line_no) + ": ";
    if (line_no == 1) {
      if (line != kJournalMagic) {
        return Status::Error(where + "not an armmimic send journal (expected '" +
                             std::string(kJournalMagic) + "')");
      }
      continue;
    }
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string kind;
    fields >> kind;
    if (kind == "program") {
      std::string field;
      while (fields >> field) {
        if (field.rfind("sha=", 0) == 0) state->hash = field.substr(4);
        if (field.rfind("lines=", 0) == 0 && !ParseNonNegative(field.substr(6), &state->lines)) {
          return Status::Error(where + "bad line count '" + field + "'");
        }
      }
      if (state->hash.empty()) return Status::Error(where + "the program line has no sha=");
      have_program = true;
    } else if (kind == "sent" || kind == "ack") {
      std::string a, b;
      fields >> a >> b;
      int index = 0, file_line = 0;
      if (!ParseNonNegative(a, &index) || !ParseNonNegative(b, &file_line) || index < 1) {
        if (in.peek() == EOF) break;  // the last record, cut short by a crash
        return Status::Error(where + "malformed '" + kind + "' record");
      }
      if (!have_program) return Status::Error(where + "'" + kind + "' before the program line");
      if (kind == "sent" && index > state->sent) {
        state->sent = index;
        state->sent_line_no = file_line;
      }
      if (kind == "ack" && index > state->acknowledged) state->acknowledged = index;
    } else if (kind == "done") {
      state->done = true;
    } else {
      // A record cut short by a crash can only be the last line; anything else is damage.
      if (in.peek() == EOF) break;
      return Status::Error(where + "unknown record '" + kind + "'");
    }
  }
  if (!have_program) return Status::Error(path + ": the journal names no program");
  return Status::Ok();
}

Status SendJournal::Open(const std::string& path, const std::string& hash, int lines,
                         const std::string& source_name, bool append) {
  Close();
  path_ = path;
  if (Status st = OpenLogFile(path, append, &file_); !st) {
    return Status::Error("cannot write the send journal: " + st.message());
  }
  if (append) return Append("# resumed");
  std::string name = source_name;
  for (char& c : name) {
    if (c == ' ' || c == '\t') c = '_';
  }
  Status s = Append(kJournalMagic);
  if (!s.ok()) return s;
  return Append("program sha=" + hash + " lines=" + std::to_string(lines) + " source=" + name);
}

Status SendJournal::Append(const std::string& record) {
  if (!file_) return Status::Error(path_ + ": the send journal is not open");
  if (std::fprintf(file_, "%s\n", record.c_str()) < 0 || !SyncOutput(file_)) {
    return Status::Error(path_ + ": cannot write the send journal: " + FileErrorText(errno));
  }
  return Status::Ok();
}

Status SendJournal::Sent(int index, int line_no) {
  return Append("sent " + std::to_string(index) + " " + std::to_string(line_no));
}

Status SendJournal::Acked(int index, int line_no, const std::string& note) {
  return Append("ack " + std::to_string(index) + " " + std::to_string(line_no) +
                (note.empty() ? "" : " " + note));
}

Status SendJournal::Done() { return Append("done"); }

void SendJournal::Close() {
  if (file_) std::fclose(file_);
  file_ = nullptr;
}

}  // namespace armmimic::robot
