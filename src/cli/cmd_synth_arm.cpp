// armmimic-cli synth arm OUTDIR: an arm scene (thesis protocol) with its ground truth.
#include <iostream>

#include "args.h"
#include "armmimic/synth/arm_scene.h"
#include "interrupt.h"
#include "progress.h"
#include "synth_commands.h"

namespace armmimic::cli {

int RunSynthArm(const std::vector<std::string>& args, const GlobalOptions& global) {
  synth::ArmSceneOptions o;
  std::vector<std::string> outdir;
  std::string codec = o.codec;
  ArgParser p(
      "synth arm",
      "  armmimic-cli synth arm OUTDIR [--seed N] [--size WxH] [--fps F]\n"
      "      [--background-frames K] [--standstill-frames M] [--frames N] [--noise S]\n"
      "      [--codec MJPG|XVID|H264] [--quality Q] [--contrast C] [--drift D] [--shadow]\n"
      "      [--head-motion] [--motion swing|bend|yaw|mixed] [--side left|right]",
      "Renders a person in a room following the thesis protocol: K frames of the empty scene,\n"
      "M standstill frames with both arms hanging, then N frames of one arm moving with known\n"
      "upper-arm and forearm directions. Writes OUTDIR/scene.avi, armlength.png (the moving arm\n"
      "straight and horizontal, thesis 5.2.3), background.png (the empty scene) and truth.tsv.\n"
      "OUTDIR is created if missing. The same seed and options give the same files.");
  p.Positionals(&outdir, "OUTDIR", 1, 1);
  p.Custom("--seed", "N", "random seed for textures, colours, noise and mixed motion (default 1)",
           [&o](const std::string& v) { return ParseSeedArg(v, &o.seed); });
  p.Custom("--size", "WxH", "frame size (default 320x240; at least 160x120)",
           [&o](const std::string& v) { return ParseSizeArg(v, &o.size); });
  p.Double("--fps", &o.fps, "F", "frame rate (default 30)");
  p.Int("--background-frames", &o.background_frames, "K", "empty-scene frames (default 45)", 0,
        100000);
  p.Int("--standstill-frames", &o.standstill_frames, "M",
        "standstill frames, arms hanging (default 60)", 0, 100000);
  p.Int("--frames", &o.motion_frames, "N", "frames of arm motion (default 150)", 1, 100000);
  p.Double("--noise", &o.noise_sigma, "S", "Gaussian sensor noise sigma, grey levels (default 3)");
  p.String("--codec", &codec, "CODEC", "MJPG (default), XVID or H264 (if an encoder is present)");
  p.Int("--quality", &o.jpeg_quality, "Q",
        "MJPG quality 1..100 with OpenCV's encoder (default 0: FFmpeg's encoder and quality)", 0,
        100);
  p.Double(
      "--contrast", &o.clothing_contrast, "C",
      "clothing contrast 0..2: 1 a dark shirt on a light wall, 0 the wall's colour (default 1)");
  p.Double("--drift", &o.lighting_drift, "D",
           "lighting drift: the gain ramps from 1 to 1+D over the video (default 0)");
  p.Flag("--shadow", &o.shadow, "a soft shadow moving over the wall during the motion");
  p.Flag("--head-motion", &o.head_motion, "the head sways and nods during the motion");
  p.Custom("--motion", "KIND",
           "swing (straight arm up and down), bend (elbow flexion), yaw (out of the image "
           "plane) or mixed (default)",
           [&o](const std::string& v) -> std::string {
             if (!synth::ParseArmMotion(v, &o.motion)) {
               return "'" + v + "' is not one of swing, bend, yaw, mixed";
             }
             return "";
           });
  p.Custom("--side", "SIDE", "side of the image the moving arm is on: right (default) or left",
           [&o](const std::string& v) -> std::string {
             if (!synth::ParseArmSide(v, &o.side)) return "'" + v + "' is not left or right";
             return "";
           });
  if (auto code = p.Parse(args)) return *code;
  for (char& c : codec) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (codec == "AVC1" || codec == "X264") codec = "H264";
  o.codec = codec;
  if (Status st = o.Check(); !st.ok()) {
    // Name the flag the bad value came from.
    const std::string& m = st.message();
    std::string flag = "--size";
    if (m.rfind("fps", 0) == 0)
      flag = "--fps";
    else if (m.rfind("background", 0) == 0)
      flag = "--background-frames";
    else if (m.rfind("standstill", 0) == 0)
      flag = "--standstill-frames";
    else if (m.rfind("motion", 0) == 0)
      flag = "--frames";
    else if (m.rfind("noise", 0) == 0)
      flag = "--noise";
    else if (m.rfind("codec", 0) == 0)
      flag = "--codec";
    else if (m.rfind("quality", 0) == 0)
      flag = "--quality";
    else if (m.rfind("clothing", 0) == 0)
      flag = "--contrast";
    else if (m.rfind("lighting", 0) == 0)
      flag = "--drift";
    return p.UsageError(flag + ": " + m);
  }

  InterruptGuard guard;
  ProgressBar bar("synth arm", o.frame_count(), global.ShowProgress());
  const Status st = synth::WriteArmScene(
      o, outdir[0], [&bar](int done, int) { bar.Update(done); }, InterruptGuard::flag());
  bar.Finish();
  if (!st.ok() && InterruptGuard::interrupted()) {
    std::cerr << "synth arm: " << InterruptGuard::Message() << "; " << outdir[0]
              << " unchanged (the scene is written whole or not at all)\n";
    return kExitFailure;
  }
  if (!st.ok()) {
    std::cerr << "armmimic-cli synth arm: " << st.message() << "\n";
    return kExitFailure;
  }
  if (!global.quiet) {
    std::cerr << "synth arm: " << o.frame_count() << " frames (" << o.background_frames
              << " background, " << o.standstill_frames << " standstill, " << o.motion_frames << " "
              << synth::ArmMotionName(o.motion) << " motion, " << synth::ArmSideName(o.side)
              << " arm) " << o.size.width << "x" << o.size.height << " " << o.codec << " -> "
              << outdir[0] << "/{scene.avi,armlength.png,background.png,truth.tsv}\n";
  }
  return kExitOk;
}

}  // namespace armmimic::cli
