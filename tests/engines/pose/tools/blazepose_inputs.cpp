// blazepose_inputs: writes BlazePose's 256x256 RGB inputs for frames of a video, each in the
// crop the pose engine would place on it seen afresh (SeedCrop: MoveNet, then BlazePose's own
// auxiliary landmarks), as binary PPM files for scripts/pose-parity.sh to run through
// TensorFlow.js. The inputs stay outside the repository; only landmark numbers are committed.
//   blazepose_inputs OUTDIR VIDEO FRAME...
#include <cstdio>
#include <iostream>
#include <string>

#include "../../tools/write_ppm.h"
#include "armmimic/core/video_source.h"
#include "armmimic/engines/pose.h"
#include "pose/blazepose.h"

using armmimic::test::WritePpm;

int main(int argc, char** argv) {
  using namespace armmimic;  // NOLINT(google-build-using-namespace): a small tool
  if (argc < 4) {
    std::cerr << "usage: blazepose_inputs OUTDIR VIDEO FRAME...\n";
    return 2;
  }
  const std::string out = argv[1], path = argv[2];
  Status st;
  auto video = VideoSource::Open(path, &st);
  auto movenet = PoseNetwork::Load("", &st);
  auto blaze = movenet ? internal::BlazePoseNetwork::Load("", &st) : nullptr;
  if (!video || !blaze) {
    std::cerr << st.message() << "\n";
    return 1;
  }
  for (int i = 3; i < argc; ++i) {
    const int index = std::stoi(argv[i]);
    Frame frame;
    if (!video->Seek(index) || !video->Read(&frame, &st)) {
      std::cerr << path << ": no frame " << index << "\n";
      return 1;
    }
    internal::BlazeCrop crop;
    if (!internal::SeedCrop(movenet.get(), blaze.get(), frame.image, PoseOptions().crop_score,
                            &crop)) {
      std::cerr << path << ": frame " << index << ": nobody seen\n";
      return 1;
    }
    const std::string file = out + "/video_" + std::to_string(index) + ".ppm";
    if (!WritePpm(file, internal::BlazePoseNetwork::MakeInput(frame.image, crop))) {
      std::cerr << file << ": cannot write\n";
      return 1;
    }
    std::cout << file << "\n";
  }
  return 0;
}
