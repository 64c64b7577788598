// The scene folder (scene.avi, armlength.png, background.png, truth.tsv) of any arm scene, and
// WriteArmScene for the fixed room.
#include <cstdio>
#include <filesystem>
#include <system_error>

#include <unistd.h>

#include <opencv2/videoio.hpp>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/image_io.h"
#include "armmimic/core/output_file.h"
#include "armmimic/synth/arm_scene.h"

namespace armmimic::synth {
namespace {

std::string Num(double v, int decimals) { return FormatNumber(v, decimals); }

}  // namespace

Status WriteSceneFolder(const ArmSceneSource& scene, const SceneVideo& video, const AngleMeta& meta,
                        const std::string& outdir, const std::function<void(int, int)>& progress,
                        const std::atomic<bool>* cancel) {
  TruthFile truth;
  truth.meta = meta;
  for (int f = 0; f < scene.frame_count(); ++f) truth.rows.push_back(scene.Truth(f).ToRow());
  return WriteSceneFolder(scene, video, truth, outdir, progress, cancel);
}

Status WriteSceneFolder(const ArmSceneSource& scene, const SceneVideo& video,
                        const TruthFile& truth, const std::string& outdir,
                        const std::function<void(int, int)>& progress,
                        const std::atomic<bool>* cancel) {
  std::error_code ec;
  std::filesystem::create_directories(outdir, ec);
  if (ec || !std::filesystem::is_directory(outdir)) {
    return Status::Error(outdir + ": cannot create the output folder" +
                         (ec ? " (" + ec.message() + ")" : std::string(" (not a folder)")));
  }
  const std::string video_path = outdir + "/scene.avi";
  // The encoder writes by name into the temporary of the one output path; it is renamed over
  // scene.avi (or the file a scene.avi link leads to) last. Discarded on every early return.
  OutputFile video_file;
  if (Status st = video_file.OpenNamed(video_path); !st) return st;
  const std::string temp_path = video_file.temp_path();
  {
    const std::string& c = video.codec;
    if (c.size() != 4) return Status::Error("codec '" + c + "' is not a four-character code");
    int api = cv::CAP_FFMPEG;
    if (c == "MJPG" && video.jpeg_quality > 0) {
      // An explicit quality needs OpenCV's own MJPEG writer, which honours it (FFmpeg's does
      // not; it gives about half the size at the same fidelity, so it is the default).
      api = cv::CAP_OPENCV_MJPEG;
    }
    const int fourcc = cv::VideoWriter::fourcc(c[0], c[1], c[2], c[3]);
    cv::VideoWriter writer;
    auto open = [&](int backend) {
      try {
        writer.open(temp_path, backend, fourcc, scene.fps(), scene.size());
      } catch (const cv::Exception&) {
        writer.release();
      }
    };
    open(api);
    if (!writer.isOpened() && c == "MJPG" && api != cv::CAP_OPENCV_MJPEG) {
      open(cv::CAP_OPENCV_MJPEG);  // always built in
    }
    if (writer.isOpened() && c == "MJPG" && video.jpeg_quality > 0) {
      writer.set(cv::VIDEOWRITER_PROP_QUALITY, video.jpeg_quality);
    }
    if (!writer.isOpened()) {
      return Status::Error(
          "arm_scene.codec",
          video_path + ": codec " + c + " has no encoder for AVI in this OpenCV build (try MJPG)");
    }
    const int n = scene.frame_count();
    for (int f = 0; f < n; ++f) {
      if (cancel && cancel->load()) {
        return Status::Error(outdir + ": cancelled after " + std::to_string(f) +
                             " frames; nothing written");
      }
      writer.write(scene.Render(f));
      if (progress) progress(f + 1, n);
    }
    writer.release();
  }
  std::error_code size_ec;
  if (std::filesystem::file_size(temp_path, size_ec) == 0 || size_ec) {
    return Status::Error(video_path + ": the " + video.codec + " encoder wrote no data");
  }
  Status st = WriteImageAtomically(outdir + "/armlength.png", scene.ArmLengthImage());
  if (!st.ok()) return st;
  st = WriteImageAtomically(outdir + "/background.png", scene.EmptyBackground());
  if (!st.ok()) return st;

  st = WriteTruthFile(outdir + "/truth.tsv", truth);
  if (!st.ok()) return st;
  // The video last, so a complete scene.avi means a complete folder.
  return video_file.Commit();
}

Status WriteArmScene(const ArmSceneOptions& options, const std::string& outdir,
                     const std::function<void(int, int)>& progress,
                     const std::atomic<bool>* cancel) {
  const Status st = options.Check();
  if (!st.ok()) return st;
  const ArmSceneRenderer renderer(options);
  const AngleMeta meta = {{"scene", "arm"},
                          {"seed", std::to_string(options.seed)},
                          {"width", std::to_string(options.size.width)},
                          {"height", std::to_string(options.size.height)},
                          {"fps", Num(options.fps, 3)},
                          {"background_frames", std::to_string(options.background_frames)},
                          {"standstill_frames", std::to_string(options.standstill_frames)},
                          {"motion_frames", std::to_string(options.motion_frames)},
                          {"motion", ArmMotionName(options.motion)},
                          {"side", ArmSideName(options.side)},
                          {"noise", Num(options.noise_sigma, 2)},
                          {"codec", options.codec},
                          {"contrast", Num(options.clothing_contrast, 2)},
                          {"drift", Num(options.lighting_drift, 3)},
                          {"shadow", options.shadow ? "yes" : "no"},
                          {"head_motion", options.head_motion ? "yes" : "no"},
                          {"upper_length_px", Num(renderer.upper_length_px(), 2)},
                          {"fore_length_px", Num(renderer.fore_length_px(), 2)}};
  return WriteSceneFolder(renderer, {options.codec, options.jpeg_quality}, meta, outdir, progress,
                          cancel);
}

}  // namespace armmimic::synth
