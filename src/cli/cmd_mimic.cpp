// armmimic-cli mimic (VIDEO --realtime | --camera N | --stream URL) --engine E ... --port DEVICE:
// live mimicking (docs/live.md). The analysis flags are analyze's, the mapping and limit flags
// plan's, the port flags send's; live::MimicRun does the work, as in the desktop application.
#include <unistd.h>
#include <QCoreApplication>
#include <QTimer>

#include <cerrno>
#include <cmath>
#include <ctime>
#include <iostream>
#include <optional>

#include "analysis_flags.h"
#include "args.h"
#include "armmimic/core/angle_file.h"
#include "armmimic/core/output_file.h"
#include "armmimic/live/mimic_run.h"
#include "armmimic/robot/live_log.h"
#include "armmimic/robot/option_tables.h"
#include "armmimic/serial/serial_link.h"
#include "command.h"
#include "flag_for_key.h"
#include "interrupt.h"
#include "planner_flags.h"
#include "port_flags.h"
#include "table_flags.h"

namespace armmimic::cli {
namespace {

int Fail(const std::string& message) {
  std::cerr << "armmimic-cli mimic: " << message << "\n";
  return kExitFailure;
}

// mimic-20240131-142501.tsv in the current folder.
std::string DefaultOutput() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char name[64];
  std::strftime(name, sizeof(name), "mimic-%Y%m%d-%H%M%S.tsv", &local);
  return name;
}

const char* kSynopsis =
    "  armmimic-cli mimic (VIDEO --realtime | --camera N | --stream URL) --engine E\n"
    "          [engine flags as analyze] (--port DEVICE | --dry-run) [-o ANGLES.tsv]\n"
    "          [--baud 9600 ...] [--profile FILE] [--map-j1 S,O ...] [--mirror]\n"
    "          [--cutoff HZ] [--deadband DEG] [--min-interval S] [--limits J2=MIN:MAX,...]\n"
    "          [--speed-limit DEG/S[,...]] [--clamp] [--stale-after S]";

const char* kDescription =
    "Analyses live and streams the arm's pose to the robot as it is measured (docs/live.md).\n"
    "Each analysed frame is planned causally with plan's mapping, limits, speed limits,\n"
    "low-pass filter (forward only: it lags sqrt(2)/(2 pi cutoff) s, 75 ms at 3 Hz) and\n"
    "deadband; one DO MOVE goes out whenever the controller has acknowledged the last and the\n"
    "target moved enough. A lost frame, an impossible jump, a target outside the limits (without\n"
    "--clamp) or no measured frame for --stale-after seconds holds the robot: it is never\n"
    "extrapolated. Every line is checked against the limits right before it is written.\n"
    "Writes the angle file (-o, default mimic-DATE-TIME.tsv), ANGLES.tsv.journal (every line\n"
    "sent and acknowledged, and the last acknowledged move) and ANGLES.tsv.latency.tsv (per\n"
    "frame: capture, analysis, planning, write and acknowledgement times), and prints a latency\n"
    "summary. Ctrl-C or SIGTERM stops cleanly: no new command, the one in flight is acknowledged,\n"
    "the angle file is kept (complete=no); a second one stops at once. Exit 0 when the input\n"
    "ends, 1 when the link is lost, the controller refuses or is silent, or on an interrupt.\n"
    "Every input (video, model, images, profile, limits, output folders) is opened and checked\n"
    "before the port: a bad one exits with nothing sent and no file written.\n";

// What the flags say: the live run's options and the port.
struct MimicSetup {
  live::MimicOptions o;
  serial::PortSettings port;
  bool dry_run = false;
  std::string output;
};

// Exactly one of VIDEO --realtime, --camera N and --stream URL, as the analysis input.
std::optional<int> PickInput(const ArgParser& p, const std::vector<std::string>& videos,
                             const std::string& camera, const std::string& stream_url,
                             bool realtime, AnalysisOptions* analysis) {
  const int sources =
      (videos.empty() ? 0 : 1) + (camera.empty() ? 0 : 1) + (stream_url.empty() ? 0 : 1);
  if (sources != 1) {
    return p.UsageError(sources == 0 ? "no input: give VIDEO --realtime, --camera N or --stream URL"
                                     : "give only one of VIDEO, --camera and --stream");
  }
  if (!videos.empty() && !realtime) {
    return p.UsageError(
        "VIDEO needs --realtime: mimic reads a file at its own frame rate, as a camera");
  }
  if (videos.empty() && realtime) {
    return p.UsageError("--realtime paces a VIDEO file; a camera or stream is live already");
  }
  int index = 0;
  if (!camera.empty() && (!ParseIntArg(camera, &index) || index < 0)) {
    return p.UsageError("--camera: '" + camera + "' is not a camera number (0, 1, ...)");
  }
  analysis->inputs = {!videos.empty()  ? videos[0]
                      : camera.empty() ? stream_url
                                       : "camera:" + camera};
  analysis->realtime = realtime;
  return std::nullopt;
}

// Parses and checks every flag into `m`. Returns the exit code when the command must end now.
std::optional<int> ParseMimic(const std::vector<std::string>& args, MimicSetup* m) {
  live::MimicOptions& o = m->o;
  AnalysisFlags analysis_flags;
  PlannerFlags planner_flags(&o.stream.planner, true);
  std::vector<std::string> videos;
  std::string camera, stream_url;
  robot::SendSettings send;  // --profile
  bool realtime = false;
  ArgParser p("mimic", kSynopsis, kDescription + AnalysisFlags::ParamList());
  p.Positionals(&videos, "VIDEO", 0, 1);
  p.Flag("--realtime", &realtime, "read VIDEO at its own frame rate, as a camera delivers it");
  p.String("--camera", &camera, "N", "analyse camera N (/dev/videoN)");
  p.String("--stream", &stream_url, "URL", "analyse a network stream (rtsp://, http://)");
  p.String("-o,--output", &m->output, "ANGLES.tsv",
           "the angle file to write (default mimic-DATE-TIME.tsv)");
  analysis_flags.Register(p, /*both_arms=*/false);
  AddPortFlags(p, &m->port);
  p.Flag("--dry-run", &m->dry_run, "print the commands with their times; open no port");
  AddRowFlag(p, *FindOptionField(robot::SendOptionFields(), "profile_path"), &send,
             WithMetavar("FILE"));
  planner_flags.RegisterMapping(p);
  planner_flags.RegisterFilter(p);
  planner_flags.RegisterLimits(p);
  for (const OptionField<robot::LiveStreamOptions>& row : robot::LiveStreamOptionFields()) {
    AddRowFlag(p, row, &o.stream);
  }
  if (auto code = p.Parse(args)) return code;
  if (auto code = PickInput(p, videos, camera, stream_url, realtime, &o.analysis)) return code;
  if (auto code = analysis_flags.Finish(p, &o.analysis)) return code;
  if (AnalysedArms(o.analysis).size() > 1) {
    return p.UsageError(
        "--side both: the robot follows one arm; name it with --side left or right");
  }
  if (!m->dry_run && m->port.port.empty()) {
    return p.UsageError("--port is required (or --dry-run; 'send --list-ports' lists the ports)");
  }
  if (const Status s = m->port.Check(); !m->dry_run && !s.ok()) return p.UsageError(Worded(s));
  if (const Status s = CheckOptionFields(robot::LiveStreamOptionFields(), "live", o.stream);
      !s.ok()) {
    return p.UsageError(Worded(s));
  }
  if (auto code = planner_flags.ParseTexts(p)) return code;
  o.stream.kind = o.analysis.engine.kind == EngineKind::kMarker ? robot::SourceKind::kMarker
                                                                : robot::SourceKind::kArm;
  if (auto code = planner_flags.Finish(p, o.stream.kind, false)) return code;
  if (m->output.empty()) m->output = DefaultOutput();
  o.angles_path = m->output;
  o.stream.source_name = o.analysis.inputs[0];
  o.stream.port_name = m->dry_run ? "dry-run" : m->port.port;
  o.stream.journal_path = m->dry_run ? "" : robot::LiveJournal::PathFor(m->output);
  o.stream.latency_path = robot::LatencyLog::PathFor(m->output);
  if (const Status s = CheckOutputKinds({{"-o", m->output},
                                         {"the journal", o.stream.journal_path},
                                         {"the latency log", o.stream.latency_path}});
      !s.ok()) {
    return p.UsageError(s.message());
  }
  if (!send.profile_path.empty()) {
    const Status s = robot::ReadProfile(send.profile_path, &o.stream.profile);
    if (!s.ok()) return Fail(Worded(s));
  }
  if (const Status s = o.stream.Check(); !s.ok()) {
    return p.UsageError(s.key().empty() ? "--profile: " + s.message() : Worded(s));
  }
  return std::nullopt;
}

// The folder of every file the run writes exists and takes a new file, so the run cannot fail
// there after the robot has been woken up.
Status CheckOutputFolders(const MimicSetup& m) {
  for (const std::string& path : {m.output, m.o.stream.journal_path, m.o.stream.latency_path}) {
    if (path.empty()) continue;
    const auto slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash + 1);
    if (::access(dir.c_str(), W_OK | X_OK) != 0) {
      return Status::Error(path + ": cannot write in its folder " + dir + ": " +
                           FileErrorText(errno));
    }
  }
  return Status::Ok();
}

void Report(const live::MimicRun& run, const MimicSetup& m, const GlobalOptions& global) {
  std::cout << "mimic: " << run.stream().Summary().Describe() << std::endl;
  if (global.quiet) return;
  const AnalysisSummary& a = run.analysis_summary();
  const robot::StreamStats& st = run.stream().planner().stats();
  std::cerr << "mimic: " << a.frames << " rows (" << a.ok << " ok, " << a.lost << " lost) in "
            << m.output << (a.cancelled ? " (complete=no)" : "") << "; " << st.flagged_jumps
            << " impossible jumps, " << st.limit_holds << " targets outside the limits, "
            << st.rate_limited << " commands held back by the speed limits\n";
  if (m.o.stream.journal_path.empty()) return;
  const int last = run.stream().last_acked_seq();
  std::cerr << "mimic: journal " << m.o.stream.journal_path << " (last acknowledged move: "
            << (last > 0 ? "command " + std::to_string(last) : std::string("none"))
            << "), latency log " << m.o.stream.latency_path << "\n";
}

int RunMimic(const std::vector<std::string>& args, const GlobalOptions& global) {
  MimicSetup m;
  if (auto code = ParseMimic(args, &m)) return *code;
  // Every input is opened and checked before the port: a bad one reaches neither the robot nor a
  // file (no angle file, journal or latency log is created).
  if (const Status s = CheckAnalysisInputs(m.o.analysis); !s.ok()) return Fail(Worded(s));
  if (const Status s = CheckOutputFolders(m); !s.ok()) return Fail(s.message());
  int argc = 1;
  char name[] = "armmimic-cli";
  char* argv[] = {name, nullptr};
  QCoreApplication app(argc, argv);
  serial::SerialLink link(robot::LinkSettings::FromProfile(m.o.stream.profile));
  if (!m.dry_run) {
    const Status s = link.Open(m.port);
    if (!s.ok()) return Fail(Worded(s));
  }
  live::MimicRun run(m.dry_run ? nullptr : &link);
  run.SetDryWriter([](const robot::LinkLine& l) {
    std::cout << (std::isnan(l.time_s) ? std::string("       -") : "t=" + FormatNumber(l.time_s, 3))
              << "\t" << l.text << std::endl;
  });
  bool ok = false;
  std::string message;
  QObject::connect(&run, &live::MimicRun::finished, &app, [&](bool result, const QString& text) {
    ok = result;
    message = text.toStdString();
    app.quit();
  });
  // The first signal stops cleanly, a second one at once (MimicRun::Stop counts them).
  InterruptGuard guard;
  int stops_seen = 0;
  QTimer poll;
  poll.setInterval(20);
  QObject::connect(&poll, &QTimer::timeout, &app, [&] {
    while (stops_seen < InterruptGuard::count()) {
      ++stops_seen;
      run.Stop(InterruptGuard::Message());
    }
  });
  poll.start();
  if (const Status s = run.Start(m.o); !s.ok()) return Fail(Worded(s));
  if (!global.quiet) {
    std::cerr << "mimic: " << m.o.analysis.inputs[0] << " -> "
              << (m.dry_run ? std::string("dry run (no port)") : m.port.port) << "; angles "
              << m.output << "; Ctrl-C stops\n";
  }
  app.exec();
  link.Close();
  Report(run, m, global);
  if (!ok)
    return Fail(message.empty() ? "stopped" : Worded(Status::Error(run.failure_key(), message)));
  return kExitOk;
}

}  // namespace

ARMMIMIC_REGISTER_COMMAND(mimic, "mimic", "analyse live and stream the arm's pose to the robot", 85,
                          RunMimic);

}  // namespace armmimic::cli
