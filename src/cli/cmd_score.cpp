// armmimic-cli score TRUTH.tsv ANGLES.tsv [--plot err.png] [--summary-only]: the error table of
// thesis Tables 5-1/6-1 and an error-vs-frame plot like Fig. 5-10.
#include <iostream>

#include "args.h"
#include "armmimic/core/angle_file.h"
#include "armmimic/core/image_io.h"
#include "armmimic/core/output_file.h"
#include "armmimic/synth/score.h"
#include "command.h"
#include "interrupt.h"

namespace armmimic::cli {
namespace {

int RunScore(const std::vector<std::string>& args, const GlobalOptions& global) {
  std::vector<std::string> files;
  std::string plot;
  bool summary_only = false;
  std::string plot_size = "800x400";
  ArgParser p("score",
              "  armmimic-cli score TRUTH.tsv ANGLES.tsv [--plot err.png] [--summary-only]",
              "Compares an angle file with the truth of a generated scene, frame by frame (rows\n"
              "are matched by frame index). Prints a table like thesis Table 5-1 (truth,\n"
              "calculated and error of the upper arm and forearm directions; yaw and bend for\n"
              "marker scenes) and a summary: coverage, the confidently wrong rate (rows ok with\n"
              "an error over 15 degrees), mean absolute direction error per segment, the axis\n"
              "error (difference mod 180, as the thesis measured orientation), maximum, yaw and\n"
              "bend errors. Exit status 0 whatever the errors; 1 when a file cannot be read or\n"
              "is malformed.");
  p.Positionals(&files, "TRUTH.tsv ANGLES.tsv", 2, 2);
  p.String("--plot", &plot, "FILE", "also draw the error against the frame into an image (.png)");
  p.String("--plot-size", &plot_size, "WxH", "size of the plot (default 800x400)");
  p.Flag("--summary-only", &summary_only, "print only the summary, not the per-frame table");
  if (auto code = p.Parse(args)) return *code;
  if (!plot.empty() && !HasImageExtension(plot)) {
    return p.UsageError("--plot " + plot + ": use an image extension (.png, .bmp, .tif, .jpg)");
  }
  cv::Size size;
  {
    const auto x = plot_size.find_first_of("xX");
    int w = 0, h = 0;
    if (x == std::string::npos || !ParseIntArg(plot_size.substr(0, x), &w) ||
        !ParseIntArg(plot_size.substr(x + 1), &h) || w < 300 || h < 200 || w > 8000 || h > 8000) {
      return p.UsageError("--plot-size '" + plot_size +
                          "' is not WxH between 300x200 and 8000x8000");
    }
    size = {w, h};
  }
  if (!plot.empty()) {
    const Status same =
        CheckOutputs({{"TRUTH.tsv", files[0]}, {"ANGLES.tsv", files[1]}}, {{"--plot", plot}});
    if (!same) return p.UsageError(same.message());
  }
  InterruptGuard guard;
  synth::TruthFile truth;
  Status st = synth::ReadTruthFile(files[0], &truth);
  if (!st.ok()) {
    std::cerr << "armmimic-cli score: " << st.message() << "\n";
    return kExitFailure;
  }
  AngleFile angles;
  st = ReadAngleFile(files[1], &angles);
  if (!st.ok()) {
    std::cerr << "armmimic-cli score: " << st.message() << "\n";
    return kExitFailure;
  }
  const synth::ScoreReport report = synth::ScoreAngles(truth, angles);
  if (!summary_only) std::cout << synth::FormatScoreTable(report) << "\n";
  std::cout << synth::FormatScoreSummary(report);
  if (report.summary.matched_frames == 0 && !global.quiet) {
    std::cerr << "armmimic-cli score: warning: no frame of " << files[1]
              << " matches a truth frame with angles in " << files[0] << "\n";
  }
  if (!plot.empty() && InterruptGuard::interrupted()) {
    std::cerr << "score: " << InterruptGuard::Message() << "; " << plot << " not written\n";
    return kExitFailure;
  }
  if (!plot.empty()) {
    st = WriteImageAtomically(plot, synth::PlotScore(report, size));
    if (!st.ok()) {
      std::cerr << "armmimic-cli score: " << st.message() << "\n";
      return kExitFailure;
    }
    if (!global.quiet) std::cerr << "score: plot -> " << plot << "\n";
  }
  return kExitOk;
}

}  // namespace

ARMMIMIC_REGISTER_COMMAND(score, "score", "compare an angle file with a scene's truth", 55,
                          RunScore);

}  // namespace armmimic::cli
