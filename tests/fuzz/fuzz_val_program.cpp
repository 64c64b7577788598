// Fuzzes the .val program reader and the safety checker send runs on every line:
//  - the reader either refuses with a message naming the file (and the line, for line errors)
//    or yields lines that are each at most the limit long, plain ASCII, not comments;
//  - the checker never accepts a line that would put a joint outside the limits, a SPEED that
//    lets a joint exceed its speed limit, or a timed move faster than the speed limit. Every
//    accepted line is re-checked here independently of the checker's own arithmetic.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "armmimic/robot/limits.h"
#include "armmimic/robot/link_protocol.h"
#include "armmimic/robot/profile.h"
#include "armmimic/robot/val_program.h"

namespace {

using armmimic::robot::JointArray;
using armmimic::robot::JointLimits;
using armmimic::robot::kJoints;

bool StartsWithLineRef(const std::string& msg, const std::string& source, int max_line) {
  if (msg.rfind(source + ":", 0) != 0) return false;
  std::size_t i = source.size() + 1;
  if (i >= msg.size() || !std::isdigit(static_cast<unsigned char>(msg[i]))) return true;  // file
  long n = 0;
  while (i < msg.size() && std::isdigit(static_cast<unsigned char>(msg[i]))) {
    n = n * 10 + (msg[i] - '0');
    if (n > 1000000000) return false;
    ++i;
  }
  return i < msg.size() && msg[i] == ':' && n >= 1 && n <= max_line;
}

void CheckInside(const JointLimits& lim, const JointArray& deg) {
  for (int j = 0; j < kJoints; ++j) {
    if (!std::isfinite(deg[j]) || deg[j] < lim.min_deg[j] || deg[j] > lim.max_deg[j]) {
      std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  // The first byte picks the line length limit (20..147), like a profile's max_line_length.
  const int max_len = 20 + (data[0] & 0x7f);
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  int newlines = 1;
  for (char c : text) newlines += c == '\n';

  std::istringstream in(text);
  armmimic::robot::ValProgram program;
  const armmimic::Status st = armmimic::robot::ParseValProgram(in, "fuzz.val", max_len, &program);
  if (!st.ok()) {
    if (!StartsWithLineRef(st.message(), "fuzz.val", newlines)) std::abort();
    return 0;
  }
  int last_line = 0;
  for (const auto& l : program.lines) {
    if (l.line_no <= last_line || l.line_no > newlines) std::abort();
    last_line = l.line_no;
    if (l.text.empty() || static_cast<int>(l.text.size()) > max_len) std::abort();
    if (l.text[0] == ';') std::abort();
    for (unsigned char c : l.text) {
      if ((c < 0x20 && c != '\t') || c >= 0x7f) std::abort();
    }
    if (!std::isnan(l.time_s) && !(l.time_s >= 0 && std::isfinite(l.time_s))) std::abort();
  }

  // send checks against the configured limits narrowed by the file's own header limits.
  armmimic::robot::ControllerProfile profile;
  profile.max_line_length = max_len;
  JointLimits limits;
  if (program.has_header_limits) {
    if (!program.header_limits.Check().ok()) std::abort();
    limits = JointLimits::Intersect(limits, program.header_limits);
  }
  if (!limits.Check().ok()) return 0;  // disjoint limits: send refuses before checking lines
  auto state = armmimic::robot::SafetyState::For(limits, profile);
  const double tol = state.tolerance_deg;
  for (const auto& l : program.lines) {
    const armmimic::robot::SafetyState before = state;
    const armmimic::Status s = armmimic::robot::CheckLine(l.text, l.time_s, state);
    if (!s.ok()) {
      if (s.message().empty()) std::abort();
      // A refused line leaves the state as it was.
      if (state.have_position != before.have_position || state.last_deg != before.last_deg ||
          state.in_editor != before.in_editor) {
        std::abort();
      }
      break;  // send stops at the first refused line
    }
    if (static_cast<int>(l.text.size()) > max_len) std::abort();
    // Independent re-check of what was accepted.
    JointArray target{};
    if (armmimic::robot::ParsePpointTarget(l.text, &target)) {
      CheckInside(limits, target);
      if (!state.have_position) std::abort();
      if (std::isnan(state.monitor_speed_pct)) std::abort();  // motion before SPEED
      if (!std::isnan(l.time_s) && !std::isnan(before.last_time_s) && before.have_position) {
        const double dt = l.time_s - before.last_time_s;
        if (!(dt > 0)) std::abort();
        for (int j = 0; j < kJoints; ++j) {
          if (std::abs(target[j] - before.last_deg[j]) > limits.max_speed_deg_s[j] * dt + tol) {
            std::abort();
          }
        }
      }
    }
    if (state.have_position) CheckInside(limits, state.last_deg);
    if (armmimic::robot::IsMotionLine(l.text) && std::isnan(state.monitor_speed_pct)) {
      std::abort();
    }
    // Once a monitor SPEED is set (nothing moves before), the SPEED settings in force keep every
    // joint at or under its speed limit.
    if (std::isnan(state.monitor_speed_pct)) continue;
    const double eff = state.monitor_speed_pct / 100.0 * state.program_speed_pct / 100.0;
    for (int j = 0; j < kJoints; ++j) {
      if (!(eff * state.joint_speed_at_100_deg_s[j] <= limits.max_speed_deg_s[j] * (1 + 1e-9))) {
        std::abort();
      }
    }
  }
  return 0;
}
