// The scene folder (scene.avi, armlength.png, background.png, truth.tsv) of any arm scene, and
// WriteArmScene for the fixed room.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <system_error>

#include <unistd.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/image_io.h"
#include "armmimic/core/output_file.h"
#include "armmimic/core/video_writer.h"
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
    Status opened;
    std::unique_ptr<VideoFileWriter> writer = VideoFileWriter::Open(
        temp_path, video.codec, scene.fps(), scene.size(), video.jpeg_quality, &opened);
    if (!writer) {
      // The message names the temporary; the user asked for scene.avi.
      std::string message = opened.message();
      if (message.rfind(temp_path, 0) == 0) message = video_path + message.substr(temp_path.size());
      // An error about the codec is about this scene's codec setting; one about the codec module
      // (a broken installation) is about none.
      return opened.key() == "codec" ? Status::Error("arm_scene.codec", message)
                                     : Status::Error(message);
    }
    const int n = scene.frame_count();
    for (int f = 0; f < n; ++f) {
      if (cancel && cancel->load()) {
        return Status::Error(outdir + ": cancelled after " + std::to_string(f) +
                             " frames; nothing written");
      }
      writer->Write(scene.Render(f));
      if (progress) progress(f + 1, n);
    }
    writer->Close();
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
