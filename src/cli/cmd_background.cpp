// armmimic-cli background VIDEO -o BG.png [--frames 45] [--start 0]: the mean of the empty
// scene (thesis 5.2.1), written atomically as an image.
#include <atomic>
#include <iostream>

#include "args.h"
#include "armmimic/core/image_io.h"
#include "armmimic/core/output_file.h"
#include "armmimic/engines/analysis.h"
#include "command.h"
#include "flag_for_key.h"
#include "interrupt.h"
#include "progress.h"

namespace armmimic::cli {
namespace {

int RunBackground(const std::vector<std::string>& args, const GlobalOptions& global) {
  std::vector<std::string> inputs;
  std::string output;
  int frames = 45;  // the thesis' background (5.2.1)
  int start = 0;
  ArgParser p("background", "  armmimic-cli background VIDEO -o BG.png [--frames 45] [--start 0]",
              "Averages frames [start, start+frames) of VIDEO, which must show the empty scene\n"
              "(thesis 5.2.1), and writes the mean as an image (format from the extension).");
  p.Positionals(&inputs, "VIDEO", 1, 1);
  p.String("-o,--output", &output, "BG.png", "the image to write (required)");
  p.Int("--frames", &frames, "N", "frames to average (default 45)", 1, 100000);
  p.Int("--start", &start, "F", "first frame to average (default 0)", 0);
  if (auto code = p.Parse(args)) return *code;
  if (output.empty()) return p.UsageError("missing -o BG.png (the image to write)");
  if (!HasImageExtension(output)) {
    return p.UsageError("-o " + output + ": use an image extension (.png, .bmp, .tif, .jpg)");
  }

  if (Status st = CheckOutputs({{"VIDEO", inputs[0]}}, {{"-o", output}}); !st) {
    return p.UsageError(st.message());
  }

  InterruptGuard guard;
  ProgressBar bar("background", frames, global.ShowProgress());
  AnalysisCallbacks cb;
  cb.cancel = InterruptGuard::flag();
  cb.on_progress = [&](int done, int) { bar.Update(done); };
  cv::Mat background;
  Status st = EstimateBackground(inputs, start, frames, &background, cb);
  bar.Finish();
  if (st && InterruptGuard::interrupted()) {
    std::cerr << "background: " << InterruptGuard::Message() << "; " << output
              << " not written (a mean of only some frames is no background)\n";
    return kExitFailure;
  }
  if (st) st = WriteImageAtomically(output, background);
  if (!st) {
    std::cerr << "armmimic-cli background: " << Worded(st) << "\n";
    return kExitFailure;
  }
  if (!global.quiet) {
    std::cerr << "background: mean of frames [" << start << ", " << start + frames << ") of "
              << inputs[0] << " -> " << output << "\n";
  }
  return kExitOk;
}

}  // namespace

ARMMIMIC_REGISTER_COMMAND(background, "background",
                          "average the empty scene of a video into a background image", 10,
                          RunBackground);

}  // namespace armmimic::cli
