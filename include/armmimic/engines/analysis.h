// Analysis: runs an engine over an input as the contract's `analyze` describes: the background
// (from an image or the first K frames), the standstill from --start, then one measurement per
// later frame. The CLI and the GUI both call this, so their angle files are identical.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/frame.h"
#include "armmimic/core/status.h"
#include "armmimic/core/video_source.h"
#include "armmimic/engines/engine_options.h"
#include "armmimic/engines/lost_reasons.h"
#include "armmimic/engines/measurement.h"
#include "armmimic/engines/pose_options.h"

namespace armmimic {

struct AnalysisOptions {
  std::vector<std::string> inputs;  // video, folder, image files or camera
  EngineOptions engine;
  std::string background_path;             // --background
  int background_frames = 0;               // --background-frames K (0: not used)
  std::string arm_length_path;             // --arm-length
  std::string reference_path;              // --reference (marker)
  int start = 0;                           // --start F: first standstill frame
  std::optional<cv::Point2d> shoulder_px;  // --shoulder X,Y
  std::optional<cv::Point2d> elbow_px;     // --elbow X,Y (lk, with --shoulder and --wrist)
  std::optional<cv::Point2d> wrist_px;     // --wrist X,Y
  std::optional<cv::Rect> roi;             // --roi X,Y,W,H
  std::string model_dir;                   // --model DIR: the pose model's folder
  // --auto-calibrate: the shoulder, elbow and wrist in frame `start` come from the pose network
  // (tracking engines), as if given with --shoulder/--elbow/--wrist.
  bool auto_calibrate = false;
  PoseSide calibrate_side = PoseSide::kAuto;  // --side with --auto-calibrate: the person's arm
  // Where the frames come from when set, instead of VideoSource::Open(inputs): called once per
  // pass over the input (the background estimate, the pose network's look at the start, the
  // analysis). `inputs` still names the source. Benchmarks run rendered scenes this way
  // (VideoSource::FromFrames).
  std::function<std::unique_ptr<VideoSource>(Status*)> open_source;
  // A video file is read at its own frame rate (FramePacer), as a camera delivers frames
  // (`mimic --realtime`). Cameras and streams are live anyway; images have no rate.
  bool realtime = false;
  Status Check() const;  // errors are keyed by the setting ("analysis.start")
};

struct AnalysisCallbacks {
  // Called once the input is open, before any frame is read (its size and frame rate).
  std::function<void(const VideoInfo&)> on_open;
  // Called for every frame the engine processed (also setup frames), in order.
  std::function<void(const Frame&, const ArmMeasurement&)> on_measurement;
  // Called for every frame of the analysis pass as soon as it is read (and, with `realtime`,
  // due), before the engine sees it, with its capture time: when it was read, or when it was
  // due for a paced file. Live consumers measure their latency from it.
  std::function<void(const Frame&, std::chrono::steady_clock::time_point captured)> on_frame;
  // Progress over the frames to process: done of total (total -1 when unknown).
  std::function<void(int done, int total)> on_progress;
  // Phase text for long setup steps ("background", "standstill", "analysis").
  std::function<void(const std::string&)> on_phase;
  const std::atomic<bool>* cancel = nullptr;  // set to stop early
  // A value the engine had to estimate rather than measure (an arm length from the region of
  // interest, ...), once, when it is decided: the shells show it so nothing is guessed silently.
  std::function<void(const std::string&)> on_estimate;
};

struct AnalysisSummary {
  int frames = 0;  // rows produced (ok + lost), over every angle file
  int ok = 0;
  int lost = 0;
  // Each angle file's rows, in ArmOutputPaths' order: one, or with the pose engine's side both
  // the person's left arm and then the right (each file then has `frames / 2` rows).
  struct ArmRows {
    PoseSide side = PoseSide::kAuto;  // the arm (as set for engines without one)
    int frames = 0, ok = 0, lost = 0;
  };
  std::vector<ArmRows> arms;
  LostReasons lost_reasons;  // why the lost rows were lost, every arm's
  double seconds = 0;        // wall time of the whole run
  bool cancelled = false;
  VideoInfo video;      // as opened (frame_count: what the file announces)
  int last_frame = -1;  // index of the last frame read, -1 if none
  AngleMeta meta;       // the (first) angle file's meta line for this run

  // Why the rows stop before the input's end (a read failed, or a video stopped clearly short of
  // the frame count it announces: see ShortOfAnnounced); empty when the input was read whole.
  // The angle file is then marked complete=no with this reason.
  std::string incomplete;

  // True when a video stopped before the frame count its header announces (a truncated or
  // damaged file; the rows stop early). Not for cancelled runs, images or cameras.
  bool EndedEarly() const {
    return !cancelled && video.kind == SourceKind::kVideo && video.frame_count > 0 &&
           last_frame + 1 < video.frame_count;
  }
  // EndedEarly by more than the estimate some containers announce may be off by: more than
  // max(2 frames, 1 % of the announced count) short (docs/angle-file.md). A smaller shortfall
  // is only a warning.
  bool ShortOfAnnounced() const {
    if (!EndedEarly()) return false;
    const int missing = video.frame_count - (last_frame + 1);
    return missing > 2 && missing * 100 > video.frame_count;
  }
};

// The arms an analysis reports, in the order of its angle files: the person's left and right arm
// for the pose engine with side both (one pass of the network gives both); one otherwise, with
// the side as set.
std::vector<PoseSide> AnalysedArms(const AnalysisOptions& options);
// The angle files an analysis writes for the output `path`: `path` itself for one arm; with side
// both one per arm, the arm's name before the last extension (A.tsv: A.left.tsv and A.right.tsv;
// a name without an extension gets .left and .right appended).
std::vector<std::string> ArmOutputPaths(const AnalysisOptions& options, const std::string& path);

// Averages frames [start, start+count) of `inputs` (thesis 5.2.1) into a CV_8UC3 image.
Status EstimateBackground(const std::vector<std::string>& inputs, int start, int count,
                          cv::Mat* background, const AnalysisCallbacks& callbacks = {});

// Runs the whole analysis; measurements go to callbacks.on_measurement.
Status RunAnalysis(const AnalysisOptions& options, const AnalysisCallbacks& callbacks,
                   AnalysisSummary* summary);

// Opens and checks every input of `options` without writing anything: the source (at least one
// frame decodes), the model, the background and arm-length images, the engine's start, and, for
// a file, that at least one frame is analysed. A live run calls it before it opens the port.
Status CheckAnalysisInputs(const AnalysisOptions& options);

// RunAnalysis writing the angle file at `output_path` (atomically; with side both, the files of
// ArmOutputPaths, each with its arm's pose.side in the header). On cancel the rows so far are
// kept in a complete file whose header says complete=no.
Status AnalyzeToFile(const AnalysisOptions& options, const std::string& output_path,
                     const AnalysisCallbacks& callbacks, AnalysisSummary* summary);

}  // namespace armmimic
