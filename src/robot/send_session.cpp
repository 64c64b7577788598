#include "armmimic/robot/send_session.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/text.h"
#include "armmimic/robot/planner.h"

namespace armmimic::robot {
namespace {

// Tolerance of the WHERE comparison: the controller prints three decimals, the program two.
constexpr double kWhereToleranceDeg = 0.1;

std::string Joints(const JointArray& j) {
  std::string s = "(";
  for (int i = 0; i < kJoints; ++i) s += (i ? "," : "") + FormatNumber(j[i], 2);
  return s + ")";
}

bool IsAngleFile(const std::string& path) {
  std::ifstream in(path);
  std::string first;
  std::getline(in, first);
  StripUtf8Bom(&first);
  return first.rfind(kAngleFileMagic, 0) == 0;
}

bool Near(const JointArray& a, const JointArray& b, double tol) {
  for (int j = 0; j < kJoints; ++j) {
    if (std::abs(a[j] - b[j]) > tol) return false;
  }
  return true;
}

bool IsMonitorSpeed(const std::string& line) {
  const std::string n = NormalizeLine(line);
  return n.rfind("SP", 0) == 0 && std::string("SPEED").rfind(n.substr(0, n.find(' ')), 0) == 0;
}

bool IsExecute(const std::string& line) { return NormalizeLine(line).rfind("EX", 0) == 0; }

}  // namespace

Status LoadProgramToSend(const std::string& path, const ControllerProfile& profile,
                         const JointLimits& limits, ValProgram* program) {
  {
    std::ifstream probe(path);
    if (!probe) return Status::Error(path + ": cannot open");
  }
  if (!IsAngleFile(path)) return ReadValProgram(path, program, profile.max_line_length);
  AngleFile angles;
  Status s = ReadAngleFile(path, &angles);
  if (!s.ok()) return s;
  PlannerOptions options;
  options.limits = limits;
  Trajectory trajectory;
  PlanReport report;
  s = PlanTrajectory(angles, options, &trajectory, &report);
  if (!s.ok()) return Status::Error(path + ": cannot plan: " + s.message());
  std::string text;
  const std::string base = path.substr(path.find_last_of('/') + 1);
  s = FormatValProgram(trajectory, profile, limits, {"source=" + base}, &text);
  if (!s.ok()) return Status::Error(path + ": " + s.message());
  std::istringstream in(text);
  return ParseValProgram(in, path + " (planned)", profile.max_line_length, program);
}

std::vector<ArmPosition> ArmPositionsAfterEachLine(const ValProgram& program) {
  std::vector<ArmPosition> after;
  bool known = false;
  JointArray at{};
  for (const ValLine& l : program.lines) {
    JointArray target{};
    if (ParsePpointTarget(l.text, &target)) {
      at = target;
      known = true;
    } else {
      const std::string n = NormalizeLine(l.text);
      int joint = 0;
      double change = 0;
      if (known && n.rfind("DO DR", 0) == 0) {
        const std::size_t sp = n.find(' ', 3);
        std::istringstream args(n.substr(sp + 1));
        char comma = 0;
        if (args >> joint >> comma >> change && joint >= 1 && joint <= kJoints) {
          at[joint - 1] += change;
        } else {
          known = false;
        }
      }
    }
    after.push_back({known, at});
  }
  return after;
}

SendSession::SendSession() = default;
SendSession::~SendSession() = default;

std::string SendSession::ResumedAt() const {
  if (start_ == 0 || start_ >= total()) return "";
  return program_.source_name + ":" + std::to_string(program_.lines[start_].line_no);
}

Status SendSession::Prepare(ValProgram program, const ControllerProfile& profile,
                            const JointLimits& limits, const std::string& input,
                            const SendStart& start) {
  program_ = std::move(program);
  profile_ = profile;
  input_ = input;
  use_journal_ = start.journal;
  limits_ =
      program_.has_header_limits ? JointLimits::Intersect(limits, program_.header_limits) : limits;
  // The whole program is checked before anything moves; each line is checked again at the port.
  {
    SafetyState state = SafetyState::For(limits_, profile_);
    const Status s = CheckProgram(program_, state);
    if (!s.ok()) return Status::Error(s.message() + " (nothing was sent)");
  }
  last_time_s_ = 0;
  bool program_mode = false;
  for (const ValLine& l : program_.lines) {
    if (!std::isnan(l.time_s)) last_time_s_ = std::max(last_time_s_, l.time_s);
    const std::string n = NormalizeLine(l.text);
    if (n.rfind("ED", 0) == 0 && std::string("EDIT").rfind(n.substr(0, n.find(' ')), 0) == 0) {
      program_mode = true;
    }
  }
  all_.clear();
  for (std::size_t i = 0; i < program_.lines.size(); ++i) {
    const ValLine& l = program_.lines[i];
    LinkLine line;
    line.text = l.text;
    line.line_no = l.line_no;
    line.index = static_cast<int>(i);
    line.time_s = l.time_s;
    // EXECUTE runs the whole program before the prompt comes back.
    line.timeout_s = !IsMotionLine(l.text) ? profile_.prompt_timeout_s
                     : IsExecute(l.text)   ? profile_.motion_timeout_s + last_time_s_
                                           : profile_.motion_timeout_s;
    all_.push_back(line);
  }
  journal_path_ = SendJournal::PathFor(input_);
  std::vector<std::string> texts;
  for (const ValLine& l : program_.lines) texts.push_back(l.text);
  hash_ = SendJournal::Hash(texts);
  Status s = DecideStart(start, hash_, program_mode);
  if (!s.ok()) return s;

  // The lines to send: the last monitor SPEED before the resume point goes out again first
  // (the controller may have been restarted), then the rest.
  to_send_.clear();
  if (start_ > 0) {
    for (std::size_t i = start_; i-- > 0;) {
      if (IsMonitorSpeed(program_.lines[i].text)) {
        to_send_.push_back(all_[i]);
        break;
      }
    }
  }
  to_send_.insert(to_send_.end(), all_.begin() + static_cast<long>(start_), all_.end());
  return Status::Ok();
}

Status SendSession::DecideStart(const SendStart& start, const std::string& hash,
                                bool program_mode) {
  start_ = 0;
  check_uncertain_ = false;
  nothing_to_do_ = false;
  const bool resuming = start.mode == SendStart::Mode::kResume || start.resume_at_line > 0;
  append_journal_ = resuming;
  if (!use_journal_) return Status::Ok();
  JournalState journal;
  {
    const Status s = SendJournal::Read(journal_path_, &journal);
    if (!s.ok() && resuming) return s;
  }
  const std::size_t total = program_.lines.size();
  if (!resuming) {
    if (journal.exists && !journal.done && journal.hash == hash && journal.sent > 0 &&
        start.mode != SendStart::Mode::kRestart && !start.dry_run) {
      // Never replay moves silently: the operator chooses between continuing and starting over.
      // The journal cannot tell a send that stopped from one still running on another terminal.
      return Status::Error(
          "send.mode", journal_path_ + ": an earlier send of " + input_ + " has not finished (" +
                           std::to_string(journal.acknowledged) + " of " + std::to_string(total) +
                           " lines acknowledged; if it is still running, let it end); resume "
                           "it where it stopped, or restart from the first line (replays "
                           "the moves already made)");
    }
    return Status::Ok();
  }
  if (!journal.exists) {
    return Status::Error("send.resume", journal_path_ +
                                            ": no journal, so nothing to resume (send it from "
                                            "the first line)");
  }
  if (journal.hash != hash) {
    return Status::Error(
        "send.resume", journal_path_ + ": the journal belongs to a different version of " + input_ +
                           " (the program changed); send it again from the "
                           "first line");
  }
  if (start.resume_at_line > 0) {
    start_ = total;
    for (std::size_t i = 0; i < total; ++i) {
      if (program_.lines[i].line_no >= start.resume_at_line) {
        start_ = i;
        break;
      }
    }
    if (start_ == total) {
      return Status::Error(
          "send.resume_at_line",
          input_ + " has no line to send at or after line " + std::to_string(start.resume_at_line));
    }
    return Status::Ok();
  }
  if (journal.done || journal.acknowledged >= static_cast<int>(total)) {
    nothing_to_do_ = true;
    start_ = total;
    return Status::Ok();
  }
  start_ = static_cast<std::size_t>(journal.acknowledged);
  check_uncertain_ = journal.uncertain();
  if (program_mode) {
    bool execute_sent = false;
    for (std::size_t i = 0; i < static_cast<std::size_t>(journal.sent) && i < total; ++i) {
      if (IsExecute(program_.lines[i].text)) execute_sent = true;
    }
    if (execute_sent) {
      return Status::Error("send.mode",
                           input_ + ":" + std::to_string(journal.sent_line_no) +
                               ": the program was started (EXECUTE) and the link was lost; it "
                               "may have run partly. Check the arm (WHERE), then send it again "
                               "from the first line or from a chosen line");
    }
    start_ = 0;  // nothing has moved yet: upload the whole program again
    check_uncertain_ = false;
  }
  return Status::Ok();
}

Status SendSession::UncertainQuery(bool* ask, LinkLine* query) const {
  *ask = false;
  if (!check_uncertain_ || start_ >= total()) return Status::Ok();
  const ValLine& l = program_.lines[start_];
  if (!IsMotionLine(l.text)) return Status::Ok();  // a SPEED does the same thing twice
  const std::string where = program_.source_name + ":" + std::to_string(l.line_no);
  if (!ArmPositionsAfterEachLine(program_)[start_].known) {
    return Status::Error("send.resume_at_line",
                         where +
                             ": the link was lost while this line was out and its target is "
                             "unknown; check the arm, then resume at line " +
                             std::to_string(l.line_no) +
                             " (send it again) or at the next line (skip it)");
  }
  query->text = "WHERE";
  query->line_no = l.line_no;
  query->index = -1;
  query->timeout_s = profile_.prompt_timeout_s;
  *ask = true;
  return Status::Ok();
}

Status SendSession::ResolveUncertain(const std::vector<std::string>& where_replies,
                                     std::string* note) {
  note->clear();
  const std::size_t i = start_;  // the uncertain line
  const ValLine& l = program_.lines[i];
  const std::string where = program_.source_name + ":" + std::to_string(l.line_no);
  JointArray now{};
  if (!ParseWhereReply(where_replies, &now)) {
    return Status::Error("send.resume_at_line",
                         where +
                             ": the controller's WHERE reply holds no six joint angles; check "
                             "the arm, then resume at a chosen line");
  }
  const std::vector<ArmPosition> expected = ArmPositionsAfterEachLine(program_);
  const JointArray& target = expected[i].joint_deg;
  const bool before_known = i > 0 && expected[i - 1].known;
  if (Near(now, target, kWhereToleranceDeg)) {
    *note = where + ": WHERE shows the arm at this line's target: it ran";
    if (use_journal_) {
      SendJournal j;
      Status s = j.Open(journal_path_, hash_, static_cast<int>(total()), input_, true);
      if (s.ok()) s = j.Acked(static_cast<int>(i) + 1, l.line_no, "where");
      if (!s.ok()) return s;
    }
    for (auto it = to_send_.begin(); it != to_send_.end(); ++it) {
      if (it->index == static_cast<int>(i)) {
        to_send_.erase(it);
        break;
      }
    }
    ++start_;
    check_uncertain_ = false;
    return Status::Ok();
  }
  if (before_known && Near(now, expected[i - 1].joint_deg, kWhereToleranceDeg)) {
    *note = where + ": WHERE shows the arm still at the previous target: sending this line again";
    check_uncertain_ = false;
    return Status::Ok();
  }
  return Status::Error("send.resume_at_line",
                       where + ": cannot tell whether this line ran: the arm is at " + Joints(now) +
                           ", the line's target is " + Joints(target) +
                           ". Check the arm, then resume at line " + std::to_string(l.line_no) +
                           " (send it again) or at the next line (skip it)");
}

Status SendSession::Attach(LinkProtocol* protocol) {
  // The safety state as of the start: every earlier line has run.
  gate_state_ = SafetyState::For(limits_, profile_);
  for (std::size_t i = 0; i < start_ && i < total(); ++i) {
    const Status s = CheckLine(program_.lines[i].text, program_.lines[i].time_s, gate_state_);
    if (!s.ok()) {
      return Status::Error(program_.source_name + ":" + std::to_string(program_.lines[i].line_no) +
                           ": " + s.message());
    }
  }
  protocol->SetGate([this](const LinkLine& l) -> std::string {
    const Status s = CheckLine(l.text, l.index >= 0 ? l.time_s : kNaN, gate_state_);
    return s.ok() ? "" : s.message();
  });
  journal_error_.clear();
  if (!use_journal_) {
    protocol->SetSentCallback(nullptr);
    protocol->SetAckCallback(nullptr);
    return Status::Ok();
  }
  {
    const bool append = start_ > 0 || append_journal_;
    const Status s = journal_.Open(journal_path_, hash_, static_cast<int>(total()), input_, append);
    if (!s.ok()) return s;
  }
  // A journal that cannot be written stops the stream: resume would not be safe without it.
  protocol->SetSentCallback([this, protocol](const LinkLine& l) {
    const Status s = journal_.Sent(l.index + 1, l.line_no);
    if (!s.ok() && journal_error_.empty()) {
      journal_error_ = s.message();
      protocol->Abort(s.message());
    }
  });
  protocol->SetAckCallback([this, protocol](const LinkLine& l, const std::vector<std::string>&) {
    const Status s = journal_.Acked(l.index + 1, l.line_no);
    if (!s.ok() && journal_error_.empty()) {
      journal_error_ = s.message();
      protocol->Abort(s.message());
    }
  });
  return Status::Ok();
}

Status SendSession::Finish(const LinkProtocol& protocol) {
  if (protocol.state() == LinkState::kDone) {
    if (!use_journal_) return Status::Ok();
    const Status s = journal_.Done();
    journal_.Close();
    return s;
  }
  journal_.Close();
  std::string message = protocol.error_message();
  if (!journal_error_.empty() && message.find(journal_error_) == std::string::npos) {
    message += " (" + journal_error_ + ")";
  }
  return Status::Error(protocol.error_key(), message);
}

bool SendSession::MotionWasInFlight(const LinkProtocol& protocol) const {
  return protocol.in_flight() && IsMotionLine(protocol.in_flight()->text);
}

}  // namespace armmimic::robot
