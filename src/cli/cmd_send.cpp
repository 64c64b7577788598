// armmimic-cli send (ANGLES.tsv | PROGRAM.val) --port DEVICE: streams a VAL program to the
// controller line by line (docs/link.md), re-checking every line against the limits right
// before it is written, with a journal beside the program so --resume loses and repeats no move.
#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <csignal>
#include <fstream>
#include <iostream>
#include <optional>

#include "args.h"
#include "armmimic/core/angle_file.h"
#include "armmimic/core/output_file.h"
#include "armmimic/robot/journal.h"
#include "armmimic/robot/link_protocol.h"
#include "armmimic/robot/option_tables.h"
#include "armmimic/robot/profile.h"
#include "armmimic/robot/send_session.h"
#include "armmimic/robot/send_setup.h"
#include "armmimic/robot/send_summary.h"
#include "armmimic/serial/link_runner.h"
#include "armmimic/serial/serial_link.h"
#include "command.h"
#include "flag_for_key.h"
#include "incomplete_input.h"
#include "interrupt.h"
#include "planner_flags.h"
#include "port_flags.h"
#include "progress.h"
#include "table_flags.h"

namespace armmimic::cli {
namespace {

struct SendOptions {
  std::vector<std::string> inputs;
  serial::PortSettings port;
  bool dry_run = false;
  bool resume = false;
  bool restart = false;
  int resume_at = 0;
  bool list_ports = false;
  bool strict = false;           // refuse an angle file marked complete=no
  robot::SendSettings settings;  // --profile, --timeout, --motion-timeout
  robot::JointLimits limits;
};

int Fail(const std::string& message) {
  std::cerr << "armmimic-cli send: " << message << "\n";
  return kExitFailure;
}

std::string Num(double v, int decimals) { return FormatNumber(v, decimals); }

std::string Interrupted() { return InterruptGuard::Message(); }

// --dry-run: every line that would be sent, with its planned time, then (on stderr) what the
// robot panel's confirmation shows: duration, start pose, ranges against the limits; no port.
int PrintDryRun(const robot::SendSession& session, const GlobalOptions& global) {
  const std::string& source = session.program().source_name;
  int moves = 0;
  for (const robot::LinkLine& l : session.lines()) {
    std::cout << (std::isnan(l.time_s) ? std::string("       -") : "t=" + Num(l.time_s, 3)) << "\t"
              << source << ":" << l.line_no << "\t" << l.text << "\n";
    if (robot::IsMotionLine(l.text)) ++moves;
  }
  if (!global.quiet) {
    std::cerr << "send --dry-run: " << session.lines().size() << " lines (" << moves
              << " motion), planned duration " << Num(session.duration_s(), 2)
              << " s; no port opened, nothing sent\n"
              << robot::FormatSendSummary(robot::SummarizeSend(session));
  }
  return kExitOk;
}

// A line written before the link died but never acknowledged: did it run? Ask the arm.
Status AskUncertain(robot::SendSession& session, serial::SerialLink& link,
                    const GlobalOptions& global) {
  bool ask = false;
  robot::LinkLine query;
  Status s = session.UncertainQuery(&ask, &query);
  if (!s.ok() || !ask) return s;
  if (!serial::RunToEnd(link, {query}, session.program().source_name, Interrupted)) {
    return Status::Error(link.protocol().error_key(),
                         link.protocol().error_message() + " (while asking WHERE)");
  }
  std::string note;
  s = session.ResolveUncertain(link.protocol().last_replies(), &note);
  if (s.ok() && !global.quiet) std::cerr << note << "\n";
  return s;
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

// Parses and checks the flags. Returns the exit code when the command must end now.
std::optional<int> ParseSend(const std::vector<std::string>& args, SendOptions* o) {
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
  p.Positionals(&o->inputs, "INPUT", 0, 1);
  AddPortFlags(p, &o->port);
  p.Flag("--dry-run", &o->dry_run, "print every line with its planned time; open no port");
  p.Flag("--resume", &o->resume, "continue after the last line the journal shows acknowledged");
  p.Flag("--restart", &o->restart,
         "start over from the first line even though the journal shows an unfinished send");
  p.Int("--resume-at", &o->resume_at, "LINE",
        "continue from this file line (after checking the arm yourself)", 1);
  p.Flag("--list-ports", &o->list_ports, "list the serial ports found and exit");
  p.Flag("--strict", &o->strict,
         "refuse an angle file marked complete=no (exit 1; without it: a warning)");
  for (const OptionField<robot::SendSettings>& row : robot::SendOptionFields()) {
    AddRowFlag(p, row, &o->settings, WithMetavar(row.kind == OptionKind::kText ? "FILE" : ""));
  }
  p.Custom("--limits", "J<n>=MIN:MAX,...", LimitsFlagHelp(),
           [&](const std::string& v) { return robot::ParseLimitsOverride(v, &o->limits); });
  AddRowFlag(p, *FindOptionField(robot::LimitsOptionFields(), "max_speed_deg_s"), &o->limits,
             WithMetavar("DEG/S[,...]"));
  if (auto code = p.Parse(args)) return code;
  if (o->list_ports) return ListPorts();
  if (o->inputs.empty()) return p.UsageError("missing the angle file or VAL program to send");
  if (!o->dry_run && o->port.port.empty()) {
    return p.UsageError("--port is required (or --dry-run; --list-ports lists the ports)");
  }
  if (o->resume && o->restart) return p.UsageError("--resume and --restart exclude each other");
  if (const Status s = o->settings.Check(); !s.ok()) return p.UsageError(Worded(s));
  {
    const Status s = o->port.Check();
    if (!o->dry_run && !s.ok()) return p.UsageError(Worded(s));
    const Status l = o->limits.Check();
    if (!l.ok()) return p.UsageError("--limits: " + l.message());
  }
  if (!o->dry_run) {
    // The journal is send's one output: it may not be the program or the profile.
    std::vector<NamedPath> inputs = {{"INPUT", o->inputs[0]}};
    if (!o->settings.profile_path.empty()) {
      inputs.push_back({"--profile", o->settings.profile_path});
    }
    const Status s =
        CheckOutputs(inputs, {{"the journal", robot::SendJournal::PathFor(o->inputs[0])}});
    if (!s.ok()) return p.UsageError(s.message());
  }
  return std::nullopt;
}

// The profile with the timeout flags, the program (planned from an angle file), and where the
// session starts (the journal, --resume, --restart).
Status PrepareSend(const SendOptions& o, robot::ControllerProfile* profile,
                   robot::SendSession* session) {
  const std::string& input = o.inputs[0];

  if (const Status s = robot::LoadSendProfile(o.settings, profile); !s.ok()) return s;

  robot::ValProgram program;
  {
    const Status s = robot::LoadProgramToSend(input, *profile, o.limits, &program);
    if (!s.ok()) return s;
  }
  robot::SendStart start = robot::StartFor(o.resume, o.restart);
  start.resume_at_line = o.resume_at;
  start.dry_run = o.dry_run;
  return session->Prepare(std::move(program), *profile, o.limits, input, start);
}

// Opens the port and streams the session's lines; the journal and the messages on the way.
int StreamToPort(const SendOptions& o, const robot::ControllerProfile& profile,
                 robot::SendSession& session, const GlobalOptions& global) {
  const std::string& input = o.inputs[0];
  const std::string& source = session.program().source_name;
  int argc = 1;
  char name[] = "armmimic-cli";
  char* argv[] = {name, nullptr};
  QCoreApplication app(argc, argv);
  InterruptGuard guard;

  serial::SerialLink link(robot::LinkSettings::FromProfile(profile));
  {
    const Status s = link.Open(o.port);
    if (!s.ok()) return Fail(Worded(s));
  }

  if (const Status s = AskUncertain(session, link, global); !s.ok()) return Fail(Worded(s));
  {
    const Status s = session.Attach(&link.protocol());
    if (!s.ok()) return Fail(Worded(s));
  }

  const std::vector<robot::LinkLine> to_send = session.lines();
  ProgressBar bar("send", static_cast<long>(to_send.size()), global.ShowProgress());
  QObject::connect(&link, &serial::SerialLink::progress, [&](int done, int) { bar.Update(done); });
  serial::RunToEnd(link, to_send, source, Interrupted);
  bar.Finish();
  link.Close();
  {
    const Status s = session.Finish(link.protocol());
    if (!s.ok() && link.protocol().state() != robot::LinkState::kDone) {
      std::cerr << "armmimic-cli send: " << Worded(s) << "\n";
      if (session.MotionWasInFlight(link.protocol())) {
        std::cerr << "armmimic-cli send: the journal " << session.journal_path()
                  << " records how far it got; 'armmimic-cli send " << input << " --port "
                  << o.port.port << " --resume' continues (it asks the arm whether the last line "
                  << "ran)\n";
      }
      return kExitFailure;
    }
    if (!s.ok()) return Fail(Worded(s));
  }
  if (!global.quiet && link.protocol().noise_lines() > 0) {
    std::cerr << "send: " << link.protocol().noise_lines()
              << " unexpected lines from the controller ignored (noise or stale prompts)\n";
  }
  if (!global.quiet) {
    const std::string resumed = session.ResumedAt();
    std::cerr << "send: " << to_send.size() << " lines acknowledged by " << o.port.port
              << (resumed.empty() ? std::string() : " (resumed at " + resumed + ")") << "\n";
  }
  return kExitOk;
}

// An angle file marked complete=no is sent with a warning, or refused with --strict. A VAL
// program, or an angle file that does not read, is left to PrepareSend's messages.
std::optional<int> CheckAngleInput(const SendOptions& o) {
  std::ifstream in(o.inputs[0], std::ios::binary);
  std::string first;
  if (!std::getline(in, first) || first.find(kAngleFileMagic) == std::string::npos) {
    return std::nullopt;
  }
  AngleFile angles;
  if (!ReadAngleFile(o.inputs[0], &angles).ok()) return std::nullopt;
  return CheckCompleteInput("send", o.inputs[0], angles, o.strict);
}

int RunSend(const std::vector<std::string>& args, const GlobalOptions& global) {
  SendOptions o;
  if (auto code = ParseSend(args, &o)) return *code;
  if (auto code = CheckAngleInput(o)) return *code;
  robot::ControllerProfile profile;
  robot::SendSession session;
  if (const Status s = PrepareSend(o, &profile, &session); !s.ok()) return Fail(Worded(s));
  if (session.nothing_to_do()) {
    if (!global.quiet) std::cout << o.inputs[0] << ": already sent completely; nothing to resume\n";
    return kExitOk;
  }
  if (o.dry_run) return PrintDryRun(session, global);
  return StreamToPort(o, profile, session, global);
}

}  // namespace

ARMMIMIC_REGISTER_COMMAND(send, "send", "stream a VAL program (or planned angles) to the robot", 80,
                          RunSend);

}  // namespace armmimic::cli
