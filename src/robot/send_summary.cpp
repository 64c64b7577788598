#include "armmimic/robot/send_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"
#include "armmimic/robot/link_protocol.h"

namespace armmimic::robot {
namespace {

// One decimal, never "-0.0" (an arm hanging reached from below, or -0.02 rounded).
std::string Deg(double v) {
  const double r = std::round(v * 10) / 10;
  return FormatNumber(r == 0 ? 0.0 : r, 1);
}

// The planned time of the last timed line before `index` (0 when there is none).
double TimeBefore(const ValProgram& program, std::size_t index) {
  for (std::size_t i = index; i-- > 0;) {
    if (!std::isnan(program.lines[i].time_s)) return program.lines[i].time_s;
  }
  return 0;
}

}  // namespace

SendSummary SummarizeSend(const SendSession& session) {
  SendSummary s;
  const ValProgram& program = session.program();
  s.lines = static_cast<int>(session.lines().size());
  for (const LinkLine& l : session.lines()) s.moves += IsMotionLine(l.text) ? 1 : 0;
  s.limits = session.limits();
  s.resumed_at = session.ResumedAt();
  const std::size_t start = session.start_index();
  bool timed = false;
  for (std::size_t i = start; i < program.lines.size(); ++i) {
    timed = timed || !std::isnan(program.lines[i].time_s);
  }
  s.duration_s = timed ? session.duration_s() - TimeBefore(program, start) : kNaN;
  const std::vector<ArmPosition> after = ArmPositionsAfterEachLine(program);
  s.total_lines = static_cast<int>(program.lines.size());
  s.remaining_lines = s.total_lines - static_cast<int>(std::min(start, program.lines.size()));
  for (std::size_t i = std::min(start, after.size()); !s.resumed_at.empty() && i-- > 0;) {
    if (!after[i].known) continue;
    s.has_resume_pose = true;
    s.resume_pose_deg = after[i].joint_deg;
    break;
  }
  for (std::size_t i = start; i < after.size(); ++i) {
    if (!after[i].known) continue;
    const JointArray& j = after[i].joint_deg;
    if (!s.has_start) {
      s.has_start = true;
      s.start_deg = j;
      s.min_deg = j;
      s.max_deg = j;
    }
    for (int k = 0; k < kJoints; ++k) {
      s.min_deg[k] = std::min(s.min_deg[k], j[k]);
      s.max_deg[k] = std::max(s.max_deg[k], j[k]);
    }
  }
  s.has_range = s.has_start;
  return s;
}

std::string FormatSendSummary(const SendSummary& s) {
  std::string out = std::to_string(s.lines) + " lines (" + std::to_string(s.moves) + " motion)";
  out += std::isnan(s.duration_s) ? ", no planned times"
                                  : ", about " + FormatNumber(s.duration_s, 1) + " s";
  if (!s.resumed_at.empty()) {
    out += ", resuming at " + s.resumed_at + ": " + std::to_string(s.remaining_lines) + " of " +
           std::to_string(s.total_lines) + " program lines still to send";
    if (s.has_resume_pose) {
      out += "\nThe arm must stand where the acknowledged lines left it:";
      for (int k = 0; k < kJoints; ++k)
        out += " J" + std::to_string(k + 1) + " " + Deg(s.resume_pose_deg[k]);
    }
  }
  out += "\nStart pose (the first target):";
  if (s.has_start) {
    for (int k = 0; k < kJoints; ++k)
      out += " J" + std::to_string(k + 1) + " " + Deg(s.start_deg[k]);
  } else {
    out += " none (no joint target in the lines to send)";
  }
  out += "\nJoint ranges against the limits:\n";
  char line[160];
  for (int k = 0; k < kJoints; ++k) {
    if (s.has_range) {
      std::snprintf(line, sizeof(line), "J%d  %8s .. %8s   (limits %.0f .. %.0f)\n", k + 1,
                    Deg(s.min_deg[k]).c_str(), Deg(s.max_deg[k]).c_str(), s.limits.min_deg[k],
                    s.limits.max_deg[k]);
    } else {
      std::snprintf(line, sizeof(line), "J%d        -           -   (limits %.0f .. %.0f)\n", k + 1,
                    s.limits.min_deg[k], s.limits.max_deg[k]);
    }
    out += line;
  }
  return out;
}

}  // namespace armmimic::robot
