// armmimic-cli send (ANGLES.tsv | PROGRAM.val) --port DEVICE: streams a VAL program to the
// controller line by line (docs/link.md), re-checking every line against the limits right
// before it is written, with a journal beside the program so --resume loses and repeats no move.
#include <QCoreApplication>
#include <QEventLoop>
#include <QTimer>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "args.h"
#include "armmimic/core/angle_file.h"
#include "armmimic/core/same_file.h"
#include "armmimic/core/text.h"
#include "armmimic/robot/journal.h"
#include "armmimic/robot/link_protocol.h"
#include "armmimic/robot/planner.h"
#include "armmimic/robot/profile.h"
#include "armmimic/robot/val_program.h"
#include "armmimic/serial/serial_link.h"
#include "command.h"
#include "interrupt.h"
#include "progress.h"

namespace armmimic::cli {
namespace {

using robot::JointArray;

struct SendOptions {
  std::vector<std::string> inputs;
  serial::PortSettings port;
  bool dry_run = false;
  bool resume = false;
  bool restart = false;
  int resume_at = 0;
  bool list_ports = false;
  std::string profile_path;
  double timeout_s = -1;
  double motion_timeout_s = -1;
  robot::JointLimits limits;
};

int Fail(const std::string& message) {
  std::cerr << "armmimic-cli send: " << message << "\n";
  return kExitFailure;
}

std::string Num(double v, int decimals) { return FormatNumber(v, decimals); }

std::string Joints(const JointArray& j) {
  std::string s = "(";
  for (int i = 0; i < robot::kJoints; ++i) s += (i ? "," : "") + Num(j[i], 2);
  return s + ")";
}

bool IsAngleFile(const std::string& path) {
  std::ifstream in(path);
  std::string first;
  std::getline(in, first);
  StripUtf8Bom(&first);
  return first.rfind(kAngleFileMagic, 0) == 0;
}

// Reads a .val program, or plans one from an angle file with the default planner options.
Status LoadProgram(const std::string& path, const robot::ControllerProfile& profile,
                   const robot::JointLimits& limits, robot::ValProgram* program) {
  {
    std::ifstream probe(path);
    if (!probe) return Status::Error(path + ": cannot open");
  }
  if (!IsAngleFile(path)) return robot::ReadValProgram(path, program, profile.max_line_length);
  AngleFile angles;
  Status s = ReadAngleFile(path, &angles);
  if (!s.ok()) return s;
  robot::PlannerOptions options;
  options.limits = limits;
  robot::Trajectory trajectory;
  robot::PlanReport report;
  s = robot::PlanTrajectory(angles, options, &trajectory, &report);
  if (!s.ok()) return Status::Error(path + ": cannot plan: " + s.message());
  std::string text;
  const std::string base = path.substr(path.find_last_of('/') + 1);
  s = robot::FormatValProgram(trajectory, profile, limits, {"source=" + base}, &text);
  if (!s.ok()) return Status::Error(path + ": " + s.message());
  std::istringstream in(text);
  return robot::ParseValProgram(in, path + " (planned)", profile.max_line_length, program);
}

// Where the arm is after each line, as far as the program tells (moves and drives).
std::vector<std::pair<bool, JointArray>> ExpectedPositions(const robot::ValProgram& program) {
  std::vector<std::pair<bool, JointArray>> after;
  bool known = false;
  JointArray at{};
  for (const robot::ValLine& l : program.lines) {
    JointArray target{};
    if (robot::ParsePpointTarget(l.text, &target)) {
      at = target;
      known = true;
    } else {
      const std::string n = robot::NormalizeLine(l.text);
      int joint = 0;
      double change = 0;
      if (known && n.rfind("DO DR", 0) == 0) {
        const std::size_t sp = n.find(' ', 3);
        std::istringstream args(n.substr(sp + 1));
        char comma = 0;
        if (args >> joint >> comma >> change && joint >= 1 && joint <= robot::kJoints) {
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

bool Near(const JointArray& a, const JointArray& b, double tol) {
  for (int j = 0; j < robot::kJoints; ++j) {
    if (std::abs(a[j] - b[j]) > tol) return false;
  }
  return true;
}

bool IsMonitorSpeed(const std::string& line) {
  const std::string n = robot::NormalizeLine(line);
  return n.rfind("SP", 0) == 0 && std::string("SPEED").rfind(n.substr(0, n.find(' ')), 0) == 0;
}

// Runs `link` over `lines` in a local event loop. Returns true when every line was acknowledged.
bool RunLink(serial::SerialLink& link, std::vector<robot::LinkLine> lines,
             const std::string& source) {
  QEventLoop loop;
  bool ok = false;
  auto done = QObject::connect(&link, &serial::SerialLink::finished, &loop, [&](bool result) {
    ok = result;
    loop.quit();
  });
  QTimer interrupt;
  interrupt.setInterval(50);
  QObject::connect(&interrupt, &QTimer::timeout, &loop, [&] {
    if (InterruptGuard::interrupted()) link.Cancel(InterruptGuard::Message());
  });
  interrupt.start();
  link.Start(std::move(lines), source);
  if (!link.protocol().finished()) loop.exec();
  QObject::disconnect(done);
  return ok || link.protocol().state() == robot::LinkState::kDone;
}

int ListPorts() {
  const std::vector<serial::PortInfo> ports = serial::ListPorts();
  if (ports.empty()) std::cerr << "armmimic-cli send: no serial ports found\n";
  for (const serial::PortInfo& p : ports) {
    std::cout << p.system_location;
    if (!p.description.empty()) std::cout << "\t" << p.description;
    if (!p.manufacturer.empty()) std::cout << "\t" << p.manufacturer;
    if (p.has_ids) {
      char ids[16];
      std::snprintf(ids, sizeof(ids), "%04x:%04x", p.vendor_id, p.product_id);
      std::cout << "\t" << ids;
    }
    std::cout << "\n";
  }
  return kExitOk;
}

int RunSend(const std::vector<std::string>& args, const GlobalOptions& global) {
  SendOptions o;
  ArgParser p("send",
              "  armmimic-cli send (ANGLES.tsv | PROGRAM.val) --port DEVICE [--baud 9600]\n"
              "          [--dry-run] [--resume] [--profile FILE]\n"
              "  armmimic-cli send --list-ports",
              "Streams a VAL program to the controller one line at a time: each line waits for "
              "its echo and the prompt before the next goes out; an error reply or a silent "
              "controller stops the stream naming the line. An angle file is planned first with "
              "the default options (as 'armmimic-cli plan'). Every line is checked against the "
              "joint and speed limits right before it is written. A journal beside the input "
              "(INPUT.journal) records each acknowledged line; --resume continues after the last "
              "one. See docs/link.md.");
  p.Positionals(&o.inputs, "INPUT", 0, 1);
  p.String("--port", &o.port.port, "DEVICE",
           "serial port, e.g. /dev/ttyUSB0; a bare name is tried as ./NAME, then /dev/NAME");
  p.Int("--baud", &o.port.baud, "N", "baud rate (default 9600)", 1, 4000000);
  p.Int("--data-bits", &o.port.data_bits, "N", "data bits 5..8 (default 8)", 5, 8);
  p.Custom("--parity", "P", "none, even or odd (default none)",
           [&](const std::string& v) { return serial::ParseParity(v, &o.port.parity); });
  p.Int("--stop-bits", &o.port.stop_bits, "N", "stop bits 1 or 2 (default 1)", 1, 2);
  p.Custom("--flow", "MODE", "flow control: none, xonxoff or rtscts (default none)",
           [&](const std::string& v) { return serial::ParseFlowControl(v, &o.port.flow); });
  p.Flag("--dry-run", &o.dry_run, "print every line with its planned time; open no port");
  p.Flag("--resume", &o.resume, "continue after the last line the journal shows acknowledged");
  p.Flag("--restart", &o.restart,
         "start over from the first line even though the journal shows an unfinished send");
  p.Int("--resume-at", &o.resume_at, "LINE",
        "continue from this file line (after checking the arm yourself)", 1);
  p.Flag("--list-ports", &o.list_ports, "list the serial ports found and exit");
  p.String("--profile", &o.profile_path, "FILE", "controller profile (docs/profiles/)");
  p.Double("--timeout", &o.timeout_s, "S",
           "seconds to wait for the prompt after a non-motion line (profile: prompt_timeout_s)");
  p.Double("--motion-timeout", &o.motion_timeout_s, "S",
           "seconds to wait for the prompt after a motion line (profile: motion_timeout_s)");
  p.Custom("--limits", "J2=-200:20,...", "override joint limits (degrees)",
           [&](const std::string& v) { return robot::ParseLimitsOverride(v, &o.limits); });
  p.Custom("--speed-limit", "DEG_S", "joint speed limits, one value or six",
           [&](const std::string& v) { return robot::ParseSpeedLimits(v, &o.limits); });
  if (auto code = p.Parse(args)) return *code;
  if (o.list_ports) return ListPorts();
  if (o.inputs.empty()) return p.UsageError("missing the angle file or VAL program to send");
  if (!o.dry_run && o.port.port.empty()) {
    return p.UsageError("--port is required (or --dry-run; --list-ports lists the ports)");
  }
  if (o.resume && o.restart) return p.UsageError("--resume and --restart exclude each other");
  if (p.Given("--timeout") && !(o.timeout_s > 0)) return p.UsageError("--timeout must be > 0");
  if (p.Given("--motion-timeout") && !(o.motion_timeout_s > 0)) {
    return p.UsageError("--motion-timeout must be > 0");
  }
  {
    const Status s = o.port.Check();
    if (!o.dry_run && !s.ok()) return p.UsageError(s.message());
    const Status l = o.limits.Check();
    if (!l.ok()) return p.UsageError("--limits: " + l.message());
  }
  const std::string& input = o.inputs[0];
  if (!o.dry_run) {
    // The journal is send's one output: it may not be the program or the profile.
    std::vector<NamedPath> inputs = {{"INPUT", input}};
    if (!o.profile_path.empty()) inputs.push_back({"--profile", o.profile_path});
    const Status s =
        CheckOutputsAreNotInputs(inputs, {{"the journal", robot::SendJournal::PathFor(input)}});
    if (!s.ok()) return p.UsageError(s.message());
  }

  robot::ControllerProfile profile = robot::ControllerProfile::Default();
  if (!o.profile_path.empty()) {
    const Status s = robot::ReadProfile(o.profile_path, &profile);
    if (!s.ok()) return Fail(s.message());
  }
  if (o.timeout_s > 0) profile.prompt_timeout_s = o.timeout_s;
  if (o.motion_timeout_s > 0) profile.motion_timeout_s = o.motion_timeout_s;

  robot::ValProgram program;
  {
    const Status s = LoadProgram(input, profile, o.limits, &program);
    if (!s.ok()) return Fail(s.message());
  }
  robot::JointLimits limits = o.limits;
  if (program.has_header_limits) {
    limits = robot::JointLimits::Intersect(limits, program.header_limits);
  }
  // The whole program is checked before anything moves; each line is checked again at the port.
  {
    robot::SafetyState state = robot::SafetyState::For(limits, profile);
    const Status s = robot::CheckProgram(program, state);
    if (!s.ok()) return Fail(s.message() + " (nothing was sent)");
  }
  const std::size_t total = program.lines.size();
  double last_time_s = 0;
  for (const robot::ValLine& l : program.lines) {
    if (!std::isnan(l.time_s)) last_time_s = std::max(last_time_s, l.time_s);
  }
  bool program_mode = false;
  for (const robot::ValLine& l : program.lines) {
    const std::string n = robot::NormalizeLine(l.text);
    if (n.rfind("ED", 0) == 0 && std::string("EDIT").rfind(n.substr(0, n.find(' ')), 0) == 0) {
      program_mode = true;
    }
  }
  std::vector<robot::LinkLine> all;
  for (std::size_t i = 0; i < total; ++i) {
    const robot::ValLine& l = program.lines[i];
    robot::LinkLine line;
    line.text = l.text;
    line.line_no = l.line_no;
    line.index = static_cast<int>(i);
    const std::string n = robot::NormalizeLine(l.text);
    const bool execute = n.rfind("EX", 0) == 0;
    line.timeout_s = !robot::IsMotionLine(l.text) ? profile.prompt_timeout_s
                     : execute                    ? profile.motion_timeout_s + last_time_s
                                                  : profile.motion_timeout_s;
    all.push_back(line);
  }

  // Where to start: the journal.
  const std::string journal_path = robot::SendJournal::PathFor(input);
  std::vector<std::string> texts;
  for (const robot::ValLine& l : program.lines) texts.push_back(l.text);
  const std::string hash = robot::SendJournal::Hash(texts);
  robot::JournalState journal_state;
  {
    const Status s = robot::SendJournal::Read(journal_path, &journal_state);
    if (!s.ok() && (o.resume || o.resume_at > 0)) return Fail(s.message());
  }
  std::size_t start = 0;
  bool check_uncertain = false;
  if (o.resume || o.resume_at > 0) {
    if (!journal_state.exists) {
      return Fail(journal_path + ": no journal, so nothing to resume (send without --resume)");
    }
    if (journal_state.hash != hash) {
      return Fail(journal_path + ": the journal belongs to a different version of " + input +
                  " (the program changed); send it again without --resume");
    }
    if (o.resume_at > 0) {
      start = total;
      for (std::size_t i = 0; i < total; ++i) {
        if (program.lines[i].line_no >= o.resume_at) {
          start = i;
          break;
        }
      }
      if (start == total) {
        return Fail("--resume-at " + std::to_string(o.resume_at) + ": " + input +
                    " has no line to send at or after it");
      }
    } else if (journal_state.done || journal_state.acknowledged >= static_cast<int>(total)) {
      if (!global.quiet) std::cout << input << ": already sent completely; nothing to resume\n";
      return kExitOk;
    } else {
      start = static_cast<std::size_t>(journal_state.acknowledged);
      check_uncertain = journal_state.uncertain();
      if (program_mode) {
        bool execute_sent = false;
        for (std::size_t i = 0; i < static_cast<std::size_t>(journal_state.sent); ++i) {
          if (robot::NormalizeLine(program.lines[i].text).rfind("EX", 0) == 0) execute_sent = true;
        }
        if (execute_sent) {
          return Fail(input + ":" + std::to_string(journal_state.sent_line_no) +
                      ": the program was started (EXECUTE) and the link was lost; it may have "
                      "run partly. Check the arm (WHERE), then send again with --restart or "
                      "--resume-at LINE");
        }
        start = 0;  // nothing has moved yet: upload the whole program again
        check_uncertain = false;
      }
    }
  } else if (journal_state.exists && !journal_state.done && journal_state.hash == hash &&
             journal_state.sent > 0 && !o.restart && !o.dry_run) {
    // Never replay moves silently: the operator chooses between continuing and starting over.
    // The journal cannot tell a send that stopped from one still running on another terminal.
    return Fail(journal_path + ": an earlier send of " + input + " has not finished (" +
                std::to_string(journal_state.acknowledged) + " of " + std::to_string(total) +
                " lines acknowledged; if it is still running, let it end); continue with "
                "--resume, or start over from the first line with --restart (replays the moves "
                "already made)");
  }

  // The lines to send: the last monitor SPEED before the resume point goes out again first
  // (the controller may have been restarted), then the rest.
  std::vector<robot::LinkLine> to_send;
  if (start > 0) {
    for (std::size_t i = start; i-- > 0;) {
      if (IsMonitorSpeed(program.lines[i].text)) {
        to_send.push_back(all[i]);
        break;
      }
    }
  }
  to_send.insert(to_send.end(), all.begin() + static_cast<long>(start), all.end());

  if (o.dry_run) {
    int moves = 0;
    for (const robot::LinkLine& l : to_send) {
      const double t = program.lines[static_cast<std::size_t>(l.index)].time_s;
      std::cout << (std::isnan(t) ? std::string("       -") : "t=" + Num(t, 3)) << "\t"
                << program.source_name << ":" << l.line_no << "\t" << l.text << "\n";
      if (robot::IsMotionLine(l.text)) ++moves;
    }
    if (!global.quiet) {
      std::cerr << "send --dry-run: " << to_send.size() << " lines (" << moves
                << " motion), planned duration " << Num(last_time_s, 2)
                << " s; no port opened, nothing sent\n";
    }
    return kExitOk;
  }

  int argc = 1;
  char name[] = "armmimic-cli";
  char* argv[] = {name, nullptr};
  QCoreApplication app(argc, argv);
  InterruptGuard guard;

  serial::SerialLink link(robot::LinkSettings::FromProfile(profile));
  {
    const Status s = link.Open(o.port);
    if (!s.ok()) return Fail(s.message());
  }

  // A line written before the link died but never acknowledged: did it run? Ask the arm.
  if (check_uncertain) {
    const std::size_t i = start;  // the uncertain line
    const robot::ValLine& l = program.lines[i];
    const std::string where = program.source_name + ":" + std::to_string(l.line_no);
    if (robot::IsMotionLine(l.text)) {
      const auto expected = ExpectedPositions(program);
      if (!expected[i].first) {
        return Fail(where +
                    ": the link was lost while this line was out and its target is "
                    "unknown; check the arm, then use --resume-at " +
                    std::to_string(l.line_no) + " (send it again) or the next line (skip it)");
      }
      robot::LinkLine query;
      query.text = "WHERE";
      query.line_no = l.line_no;
      query.index = -1;
      query.timeout_s = profile.prompt_timeout_s;
      if (!RunLink(link, {query}, program.source_name)) {
        return Fail(link.protocol().error_message() + " (while asking WHERE)");
      }
      JointArray now{};
      if (!robot::ParseWhereReply(link.protocol().last_replies(), &now)) {
        return Fail(where +
                    ": the controller's WHERE reply holds no six joint angles; check "
                    "the arm, then use --resume-at");
      }
      const double tol = 0.1;
      const JointArray& target = expected[i].second;
      const bool before_known = i > 0 && expected[i - 1].first;
      if (Near(now, target, tol)) {
        if (!global.quiet) {
          std::cerr << where << ": WHERE shows the arm at this line's target: it ran\n";
        }
        robot::SendJournal j;
        Status s = j.Open(journal_path, hash, static_cast<int>(total), input, true);
        if (s.ok()) s = j.Acked(static_cast<int>(i) + 1, l.line_no, "where");
        if (!s.ok()) return Fail(s.message());
        // Drop it from the stream.
        for (auto it = to_send.begin(); it != to_send.end(); ++it) {
          if (it->index == static_cast<int>(i)) {
            to_send.erase(it);
            break;
          }
        }
        ++start;
      } else if (before_known && Near(now, expected[i - 1].second, tol)) {
        if (!global.quiet) {
          std::cerr << where
                    << ": WHERE shows the arm still at the previous target: sending "
                       "this line again\n";
        }
      } else {
        return Fail(where + ": cannot tell whether this line ran: the arm is at " + Joints(now) +
                    ", the line's target is " + Joints(target) +
                    ". Check the arm, then use --resume-at " + std::to_string(l.line_no) +
                    " (send it again) or the next line (skip it)");
      }
    }
  }

  // The safety state as of the resume point: every earlier line has run.
  robot::SafetyState gate_state = robot::SafetyState::For(limits, profile);
  for (std::size_t i = 0; i < start; ++i) {
    const Status s = robot::CheckLine(program.lines[i].text, program.lines[i].time_s, gate_state);
    if (!s.ok()) {
      return Fail(program.source_name + ":" + std::to_string(program.lines[i].line_no) + ": " +
                  s.message());
    }
  }
  link.protocol().SetGate([&](const robot::LinkLine& l) -> std::string {
    const double t = l.index >= 0 ? program.lines[static_cast<std::size_t>(l.index)].time_s : kNaN;
    const Status s = robot::CheckLine(l.text, t, gate_state);
    return s.ok() ? "" : s.message();
  });

  robot::SendJournal journal;
  {
    const bool append = start > 0 || o.resume || o.resume_at > 0;
    const Status s = journal.Open(journal_path, hash, static_cast<int>(total), input, append);
    if (!s.ok()) return Fail(s.message());
  }
  // A journal that cannot be written stops the stream: resume would not be safe without it.
  std::string journal_error;
  link.protocol().SetSentCallback([&](const robot::LinkLine& l) {
    const Status s = journal.Sent(l.index + 1, l.line_no);
    if (!s.ok() && journal_error.empty()) {
      journal_error = s.message();
      link.protocol().Abort(s.message());
    }
  });
  link.protocol().SetAckCallback([&](const robot::LinkLine& l, const std::vector<std::string>&) {
    const Status s = journal.Acked(l.index + 1, l.line_no);
    if (!s.ok() && journal_error.empty()) {
      journal_error = s.message();
      link.protocol().Abort(s.message());
    }
  });

  ProgressBar bar("send", static_cast<long>(to_send.size()), global.ShowProgress());
  QObject::connect(&link, &serial::SerialLink::progress, [&](int done, int) { bar.Update(done); });
  const std::size_t sent_count = to_send.size();
  const bool ok = RunLink(link, std::move(to_send), program.source_name);
  bar.Finish();
  link.Close();
  if (!ok) {
    std::string message = link.protocol().error_message();
    if (!journal_error.empty() && message.find(journal_error) == std::string::npos) {
      message += " (" + journal_error + ")";
    }
    std::cerr << "armmimic-cli send: " << message << "\n";
    if (link.protocol().in_flight() && robot::IsMotionLine(link.protocol().in_flight()->text)) {
      std::cerr << "armmimic-cli send: the journal " << journal_path
                << " records how far it got; 'armmimic-cli send " << input << " --port "
                << o.port.port << " --resume' continues (it asks the arm whether the last line "
                << "ran)\n";
    }
    return kExitFailure;
  }
  {
    const Status s = journal.Done();
    if (!s.ok()) return Fail(s.message());
  }
  if (!global.quiet && link.protocol().noise_lines() > 0) {
    std::cerr << "send: " << link.protocol().noise_lines()
              << " unexpected lines from the controller ignored (noise or stale prompts)\n";
  }
  if (!global.quiet) {
    std::cerr << "send: " << sent_count << " lines acknowledged by " << o.port.port
              << (start > 0 && start < total
                      ? " (resumed at " + program.source_name + ":" +
                            std::to_string(program.lines[start].line_no) + ")"
                      : std::string())
              << "\n";
  }
  return kExitOk;
}

}  // namespace

ARMMIMIC_REGISTER_COMMAND(send, "send", "stream a VAL program (or planned angles) to the robot", 80,
                          RunSend);

}  // namespace armmimic::cli
