// pose_inputs: writes the pose network's 192x192 RGB inputs (whole frame padded to a square, as
// the pose engine's first frame) as binary PPM files, for scripts/pose-parity.sh to run through
// TensorFlow.js. The inputs stay outside the repository; only keypoint numbers are committed.
//   pose_inputs OUTDIR video PATH FRAME...    frames of a video
//   pose_inputs OUTDIR synth SEED FRAME...    frames of `armmimic-cli synth arm --seed SEED`
#include <cstdio>
#include <iostream>
#include <string>

#include <opencv2/videoio.hpp>

#include "armmimic/core/video_source.h"
#include "armmimic/engines/pose.h"
#include "armmimic/synth/arm_scene.h"
#include "write_ppm.h"

using armmimic::test::WritePpm;

int main(int argc, char** argv) {
  if (argc < 5) {
    std::cerr << "usage: pose_inputs OUTDIR (video PATH | synth SEED) FRAME...\n";
    return 2;
  }
  const std::string out = argv[1], kind = argv[2], what = argv[3];
  std::unique_ptr<armmimic::synth::ArmSceneRenderer> scene;
  std::unique_ptr<armmimic::VideoSource> video;
  armmimic::Status st;
  if (kind == "synth") {
    armmimic::synth::ArmSceneOptions o;
    o.seed = std::stoull(what);
    scene = std::make_unique<armmimic::synth::ArmSceneRenderer>(o);
  } else {
    video = armmimic::VideoSource::Open(what, &st);
    if (!video) {
      std::cerr << st.message() << "\n";
      return 1;
    }
  }
  for (int i = 4; i < argc; ++i) {
    const int index = std::stoi(argv[i]);
    cv::Mat bgr;
    if (scene) {
      bgr = scene->Render(index);
    } else {
      armmimic::Frame frame;
      if (!video->Seek(index) || !video->Read(&frame, &st)) {
        std::cerr << what << ": no frame " << index << "\n";
        return 1;
      }
      bgr = frame.image;
    }
    const cv::Mat rgb = armmimic::PoseNetwork::MakeInput(bgr, armmimic::WholeImageCrop(bgr.size()));
    const std::string path = out + "/" + kind + "_" + std::to_string(index) + ".ppm";
    if (!WritePpm(path, rgb)) {
      std::cerr << path << ": cannot write\n";
      return 1;
    }
    std::cout << path << "\n";
  }
  return 0;
}
