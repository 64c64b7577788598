// Fuzzes the controller profile reader: any bytes either fail with a message that names the
// file and line (or, for a value that is wrong only as a whole, the file and the key), or give
// a profile that passes its own check and survives a write/read round trip unchanged.
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "armmimic/robot/profile.h"

namespace {

const char* const kKeys[] = {"terminator",
                             "prompt_top",
                             "prompt_running",
                             "error_prefix",
                             "max_line_length",
                             "decimals",
                             "program_name",
                             "prompt_timeout_s",
                             "motion_timeout_s",
                             "end_edit_line",
                             "speed_template",
                             "move_template",
                             "drive_template",
                             "edit_template",
                             "execute_template",
                             "program_move_template",
                             "joint_speed_at_100_deg_s"};

bool NamesLineOrKey(const std::string& msg, int max_line) {
  const std::string src = "fuzz.profile:";
  if (msg.rfind(src, 0) != 0) return false;
  std::size_t i = src.size();
  if (i < msg.size() && std::isdigit(static_cast<unsigned char>(msg[i]))) {
    long n = 0;
    while (i < msg.size() && std::isdigit(static_cast<unsigned char>(msg[i]))) {
      n = n * 10 + (msg[i] - '0');
      if (n > 1000000000) return false;
      ++i;
    }
    return i < msg.size() && msg[i] == ':' && n >= 1 && n <= max_line;
  }
  if (msg.compare(i, 11, " read error") == 0) return true;
  // A value wrong only as a whole (ControllerProfile::Check): "file: key: why".
  if (msg.compare(i, 1, " ") != 0) return false;
  const std::size_t colon = msg.find(':', i + 1);
  if (colon == std::string::npos) return false;
  const std::string key = msg.substr(i + 1, colon - i - 1);
  for (const char* k : kKeys) {
    if (key == k) return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  int lines = 1;
  for (char c : text) lines += c == '\n';
  std::istringstream in(text);
  armmimic::robot::ControllerProfile p;
  const armmimic::Status st = armmimic::robot::ParseProfile(in, "fuzz.profile", &p);
  if (!st.ok()) {
    if (!NamesLineOrKey(st.message(), lines)) {
      std::fprintf(stderr, "message names neither line nor key: %s\n", st.message().c_str());
      std::abort();
    }
    return 0;
  }
  if (!p.Check().ok()) std::abort();
  const std::string written = armmimic::robot::FormatProfile(p);
  std::istringstream again(written);
  armmimic::robot::ControllerProfile q;
  const armmimic::Status back = armmimic::robot::ParseProfile(again, "again.profile", &q);
  if (!back.ok() || armmimic::robot::FormatProfile(q) != written) {
    std::fprintf(stderr, "round trip failed: %s\n--- written:\n%s\n--- read back:\n%s\n",
                 back.message().c_str(), written.c_str(),
                 armmimic::robot::FormatProfile(q).c_str());
    std::abort();
  }
  return 0;
}
