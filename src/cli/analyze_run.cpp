#include "analyze_run.h"
#include "flag_for_key.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "armmimic/core/output_file.h"
#include "armmimic/core/text.h"
#include "interrupt.h"
#include "progress.h"

namespace armmimic::cli {
namespace {

std::string BaseName(std::string path) {
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The outcome of one analysis, for the one-line report and the summary table.
struct Outcome {
  Status status;
  AnalysisSummary summary;
  int frames_read = 0;
};

// Runs one analysis with a progress bar labelled `label`; `quiet` drops the estimate notes.
Outcome Run(const AnalysisOptions& o, const std::string& output, const std::string& label,
            const GlobalOptions& global) {
  Outcome out;
  ProgressBar bar(label, -1, global.ShowProgress());
  AnalysisCallbacks cb;
  cb.cancel = InterruptGuard::flag();
  cb.on_phase = [&](const std::string& phase) { bar.SetLabel(label + " " + phase); };
  cb.on_progress = [&](int done, int total) {
    bar.SetTotal(total);
    bar.Update(done);
    out.frames_read = done;
  };
  cb.on_estimate = [&](const std::string& text) {
    if (global.quiet) return;
    bar.Finish();  // clears the bar line; the next update draws it again
    std::cerr << "analyze: estimated: " << text << "\n";
  };
  out.status = AnalyzeToFile(o, output, cb, &out.summary);
  bar.Finish();
  return out;
}

// The angle files a run writes for `output`, for messages: "A.tsv", or with side both
// "A.left.tsv and A.right.tsv".
std::string FilesText(const AnalysisOptions& o, const std::string& output) {
  std::string text;
  for (const std::string& path : ArmOutputPaths(o, output)) {
    text += (text.empty() ? "" : " and ") + path;
  }
  return text;
}

std::string Source(const AnalysisOptions& o, const Outcome& r) {
  return r.summary.video.path.empty() ? o.inputs[0] : r.summary.video.path;
}

// The end-of-run lines shared by both modes: the truncation warning and the rows report.
void Report(const AnalysisOptions& o, const std::string& output, const Outcome& r,
            const GlobalOptions& global) {
  const AnalysisSummary& s = r.summary;
  if (s.EndedEarly() && s.incomplete.empty()) {
    // Not an error (every row written is valid), but the operator must know rows stop early.
    std::cerr << "armmimic-cli analyze: warning: " << Source(o, r) << ": the file announces "
              << s.video.frame_count << " frames but only " << s.last_frame + 1
              << " could be read (truncated or damaged video); the rows stop at frame "
              << s.last_frame << "\n";
  }
  if (!global.quiet) {
    char rate[64];
    std::snprintf(rate, sizeof(rate), "%.2f s, %.0f frames/s", s.seconds,
                  s.seconds > 0 ? r.frames_read / s.seconds : 0.0);
    const std::vector<std::string> paths = ArmOutputPaths(o, output);
    if (paths.size() == 1 || paths.size() != s.arms.size()) {
      std::cerr << "analyze: " << s.frames << " rows (" << s.ok << " ok, " << s.lost
                << " lost) from " << BaseName(Source(o, r)) << " in " << rate << " -> " << output
                << "\n";
    } else {
      // One file per arm, each with a row for every frame.
      std::cerr << "analyze: " << s.arms.front().frames << " rows per arm from "
                << BaseName(Source(o, r)) << " in " << rate << " ->";
      for (std::size_t i = 0; i < paths.size(); ++i) {
        std::cerr << (i ? "," : "") << " " << paths[i] << " (" << s.arms[i].ok << " ok, "
                  << s.arms[i].lost << " lost)";
      }
      std::cerr << "\n";
    }
    if (s.lost > 0) {
      std::cerr << "analyze: lost rows: " << s.lost_reasons.Text(LostReasons::kReported) << "\n";
    }
  }
}

// A name or message in the summary: escaped (\t, \n, \r, \\), never rewritten, so a
// script gets every name back as it was (docs/batch.md).
std::string Cell(const std::string& text) { return EscapeTsvField(text); }

struct SummaryRow {
  std::string video;
  std::string output;        // the angle file as planned (A.tsv; with side both A.left.tsv ...)
  bool angles_shown = true;  // false for a video that ran and wrote none
  std::string status = "skipped", error;
  AnalysisSummary summary;
};

// One line per angle file: per video, or with side both per video and arm.
std::string SummaryText(const std::vector<SummaryRow>& rows, const AnalysisOptions& options) {
  std::string text = "video\tangles\tframes\tok\tlost\tcoverage\tseconds\tstatus\terror\n";
  for (const SummaryRow& r : rows) {
    const AnalysisSummary& s = r.summary;
    const bool ran = r.status != "skipped";
    const std::vector<std::string> paths = ArmOutputPaths(options, r.output);
    for (std::size_t i = 0; i < paths.size(); ++i) {
      AnalysisSummary::ArmRows n{PoseSide::kAuto, s.frames, s.ok, s.lost};
      if (paths.size() > 1) n = i < s.arms.size() ? s.arms[i] : AnalysisSummary::ArmRows();
      const double coverage = n.frames > 0 ? static_cast<double>(n.ok) / n.frames : kNaN;
      text += Cell(r.video) + "\t" + (r.angles_shown ? Cell(paths[i]) : "") + "\t" +
              std::to_string(n.frames) + "\t" + std::to_string(n.ok) + "\t" +
              std::to_string(n.lost) + "\t" + FormatNumber(coverage, 3) + "\t" +
              (ran ? FormatNumber(s.seconds, 2) : "nan") + "\t" + r.status + "\t" + Cell(r.error) +
              "\n";
    }
  }
  return text;
}

}  // namespace

int AnalyzeOne(const AnalysisOptions& o, const std::string& output, const GlobalOptions& global) {
  const Outcome r = Run(o, output, "analyze", global);
  if (!r.status) {
    std::cerr << "armmimic-cli analyze: " << Worded(r.status) << "\n";
    return kExitFailure;
  }
  if (r.summary.cancelled) {
    std::cerr << "analyze: " << InterruptGuard::Message() << "; ";
    if (r.summary.meta.empty()) {
      std::cerr << "no row yet, " << FilesText(o, output) << " not written\n";
    } else {
      std::cerr << r.summary.frames << " rows kept in " << FilesText(o, output)
                << " (marked complete=no)\n";
    }
    return kExitFailure;
  }
  Report(o, output, r, global);
  if (!r.summary.incomplete.empty()) {
    std::cerr << "armmimic-cli analyze: " << Source(o, r) << ": " << r.summary.incomplete << "; "
              << r.summary.frames << " rows kept in " << FilesText(o, output)
              << " (marked complete=no)\n";
    return kExitFailure;
  }
  return kExitOk;
}

BatchPlan PlanBatch(const std::vector<std::string>& videos, const std::string& dir,
                    const std::string& summary) {
  BatchPlan plan;
  plan.videos = videos;
  const std::string folder = dir.empty() || dir.back() == '/' ? dir : dir + "/";
  for (const std::string& v : videos) {
    std::string name = BaseName(v);
    const auto dot = name.find_last_of('.');
    if (dot != std::string::npos && dot > 0) name.erase(dot);
    plan.outputs.push_back(folder + name + ".tsv");
  }
  plan.summary = summary.empty() ? folder + "summary.tsv" : summary;
  return plan;
}

int AnalyzeBatch(const AnalysisOptions& options, const BatchPlan& plan,
                 const GlobalOptions& global) {
  const std::size_t n = plan.videos.size();
  std::vector<SummaryRow> rows(n);
  int failed = 0;
  for (std::size_t i = 0; i < n; ++i) {
    rows[i].video = plan.videos[i];
    rows[i].output = plan.outputs[i];  // a skipped video's: where a rerun writes it
  }
  for (std::size_t i = 0; i < n && !InterruptGuard::interrupted(); ++i) {
    AnalysisOptions o = options;
    o.inputs = {plan.videos[i]};
    const std::string label = "[" + std::to_string(i + 1) + "/" + std::to_string(n) + "]";
    if (!global.quiet) std::cerr << "analyze: " << label << " " << plan.videos[i] << "\n";
    const Outcome r = Run(o, plan.outputs[i], label, global);
    SummaryRow& row = rows[i];
    row.summary = r.summary;
    // The file exists once its header went out: complete, incomplete or interrupted with rows.
    if (!r.status || r.summary.meta.empty()) row.angles_shown = false;
    if (!r.status) {
      row.status = "failed";
      row.error = Worded(r.status);
      ++failed;
      std::cerr << "armmimic-cli analyze: " << label << " " << Worded(r.status) << "\n";
    } else if (r.summary.cancelled) {
      row.status = "interrupted";
      row.error = InterruptGuard::Message() +
                  (r.summary.meta.empty() ? "; not written" : "; rows kept, marked complete=no");
      std::cerr << "analyze: " << label << " " << InterruptGuard::Message() << "; "
                << (r.summary.meta.empty()
                        ? FilesText(o, plan.outputs[i]) + " not written"
                        : std::to_string(r.summary.frames) + " rows kept in " +
                              FilesText(o, plan.outputs[i]) + " (marked complete=no)")
                << "\n";
    } else if (!r.summary.incomplete.empty()) {
      row.status = "incomplete";
      row.error = r.summary.incomplete + "; rows kept, marked complete=no";
      Report(o, plan.outputs[i], r, global);
      std::cerr << "armmimic-cli analyze: " << label << " " << Source(o, r) << ": "
                << r.summary.incomplete << " (marked complete=no)\n";
    } else {
      row.status = "ok";
      if (r.summary.EndedEarly()) row.error = "the video ended early (truncated or damaged)";
      Report(o, plan.outputs[i], r, global);
    }
  }
  const Status st = WriteOutputFile(plan.summary, SummaryText(rows, options));
  if (!st) {
    std::cerr << "armmimic-cli analyze: " << st.message() << "\n";
    return kExitFailure;
  }
  int done = 0;
  for (const SummaryRow& r : rows) done += r.status == "ok" ? 1 : 0;
  if (!global.quiet || done < static_cast<int>(n)) {
    std::cerr << "analyze: " << done << " of " << n << " videos analysed";
    if (failed > 0) std::cerr << ", " << failed << " failed";
    int incomplete = 0;
    for (const SummaryRow& r : rows) incomplete += r.status == "incomplete" ? 1 : 0;
    if (incomplete > 0) std::cerr << ", " << incomplete << " incomplete";
    if (InterruptGuard::interrupted()) std::cerr << ", " << InterruptGuard::Message();
    std::cerr << " -> " << plan.summary << "\n";
  }
  return done == static_cast<int>(n) ? kExitOk : kExitFailure;
}

Status ReadVideoList(const std::string& path, std::vector<std::string>* videos) {
  if (Status st = CheckInputFile(path); !st) return Status::Error("--list " + st.message());
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::Error("--list " + path + ": cannot open (" + FileErrorText(errno) + ")");
  std::string line;
  int line_no = 0;
  videos->clear();
  while (ReadTextLine(in, &line)) {  // LF, CRLF or a CR alone
    if (++line_no == 1) StripUtf8Bom(&line);
    const std::string entry = Trim(line);
    if (entry.empty() || entry[0] == '#') continue;
    videos->push_back(entry);
  }
  if (in.bad()) return Status::Error("--list " + path + ": read error");
  return Status::Ok();
}

}  // namespace armmimic::cli
