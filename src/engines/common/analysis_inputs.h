// What an analysis reads before its engine starts, shared by the run (analysis.cpp) and the
// standstill estimate made ahead of it (standstill_estimate.cpp): the input, an image of the
// input's size, and the mean of a stretch of frames.
#pragma once

#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "armmimic/core/status.h"
#include "armmimic/core/video_source.h"
#include "armmimic/engines/analysis.h"

namespace armmimic::internal {

std::string SizeText(const cv::Size& s);  // "320x240"

// The input of a pass: options.open_source when set, else the files named in options.inputs.
std::unique_ptr<VideoSource> OpenInput(const AnalysisOptions& options, Status* status);

// Loads the image the setting `key` names (`what`: "the background image") and checks its size
// against the video's.
Status LoadSized(const std::string& path, const std::string& key, const std::string& what,
                 const VideoInfo& video, cv::Mat* out);

// Averages frames [start, start+count) of `source` (a float sum, one rounding to 8 bits) into a
// CV_8UC3 image; `open_status` is returned when the source could not be opened. `what` names
// the stretch in errors ("the background", "the standstill"). A cancelled run stops early with
// Ok.
Status MeanOfFrames(std::unique_ptr<VideoSource> source, const Status& open_status, int start,
                    int count, const std::string& what, cv::Mat* mean,
                    const AnalysisCallbacks& callbacks = {});

}  // namespace armmimic::internal
