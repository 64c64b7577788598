// The two ways `analyze` runs once its options are settled: one input into one angle file, or a
// batch (one angle file per video in an output folder, plus a summary table). Both stop cleanly
// on SIGINT, SIGTERM or SIGHUP (interrupt.h).
#pragma once

#include <string>
#include <vector>

#include "armmimic/engines/analysis.h"
#include "command.h"

namespace armmimic::cli {

// Analyses options.inputs into `output`. Returns the exit code.
int AnalyzeOne(const AnalysisOptions& options, const std::string& output,
               const GlobalOptions& global);

struct BatchPlan {
  std::vector<std::string> videos;   // one input each (a video, or a folder of images)
  std::vector<std::string> outputs;  // the angle file of each video, in the same order
  std::string summary;               // the summary table
};

// The angle file of each video in `dir`: its name without the extension, plus ".tsv".
BatchPlan PlanBatch(const std::vector<std::string>& videos, const std::string& dir,
                    const std::string& summary);

// Analyses every video of `plan` with `options` (whose inputs are replaced by each video), one
// after the other; a failing video does not stop the others. Writes the summary table. Returns
// 0 when every video was analysed, 1 when one failed or an interrupt stopped the batch.
int AnalyzeBatch(const AnalysisOptions& options, const BatchPlan& plan,
                 const GlobalOptions& global);

// Reads a list file: one video per line; blank lines and lines starting with '#' are skipped,
// a UTF-8 byte order mark and CRLF line ends are accepted. Relative paths are taken from the
// current folder, as the shell would.
Status ReadVideoList(const std::string& path, std::vector<std::string>* videos);

}  // namespace armmimic::cli
