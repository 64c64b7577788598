// SendSummary: what an operator is shown before a send moves the arm, over the lines that will be
// written (after a resume, only the rest): how many, how long, where the arm goes first, and each
// joint's range against its limits. The robot panel's confirmation and `send --dry-run` show it.
#pragma once

#include <string>

#include "armmimic/robot/limits.h"
#include "armmimic/robot/send_session.h"

namespace armmimic::robot {

struct SendSummary {
  int lines = 0;           // lines to write
  int moves = 0;           // of them, motion lines
  double duration_s = 0;   // planned time from the first line to the last (NaN: not timed)
  bool has_start = false;  // the program names a target at or after the start
  JointArray start_deg{};  // the first pose the arm is sent to
  bool has_range = false;
  JointArray min_deg{};  // the range of the poses from the start on
  JointArray max_deg{};
  JointLimits limits;      // the limits every line is checked against
  std::string resumed_at;  // "PROGRAM.val:12" after a resume, else ""
  // After a resume: the program's lines not yet acknowledged (of `total_lines`), and where the
  // acknowledged ones left the arm, which is where it must stand before the rest moves it.
  int remaining_lines = 0;
  int total_lines = 0;
  bool has_resume_pose = false;
  JointArray resume_pose_deg{};
};

// After SendSession::Prepare.
SendSummary SummarizeSend(const SendSession& session);
// Several lines of plain text (degrees with one decimal, the limits as whole degrees).
std::string FormatSendSummary(const SendSummary& summary);

}  // namespace armmimic::robot
