// armmimic-cli synth arm OUTDIR: an arm scene (thesis protocol) with its ground truth.
// Length: RunSynthArm is the subcommand's flag table and its checks, one list in --help order.
#include <iostream>

#include "args.h"
#include "armmimic/synth/arm_scene.h"
#include "armmimic/synth/capsule_arm_scene.h"
#include "armmimic/synth/random_arm_scene.h"
#include "flag_for_key.h"
#include "synth_commands.h"

namespace armmimic::cli {
namespace {

// The flags a random scene draws from its seed instead.
const char* const kDrawnFlags[] = {"--fps",
                                   "--background-frames",
                                   "--standstill-frames",
                                   "--frames",
                                   "--noise",
                                   "--codec",
                                   "--quality",
                                   "--contrast",
                                   "--drift",
                                   "--shadow",
                                   "--head-motion",
                                   "--motion",
                                   "--side"};

int WriteRandom(const synth::RandomArmSceneOptions& o, const std::string& outdir,
                const GlobalOptions& global) {
  const synth::RandomArmScene scene(o);
  if (const int code = WriteSceneWithProgress(
          "arm", scene.frame_count(), global,
          [&](const auto& progress, const auto* cancel) {
            return synth::WriteSceneFolder(scene, {"MJPG", scene.params().jpeg_quality},
                                           synth::RandomSceneMeta(scene), outdir, progress, cancel);
          },
          outdir + " unchanged (the scene is written whole or not at all)");
      code != kExitOk) {
    return code;
  }
  if (!global.quiet) {
    const synth::RandomSceneParams& p = scene.params();
    std::cerr << "synth arm: random " << synth::SceneTierName(o.tier) << " scene, seed " << o.seed
              << ": " << scene.frame_count() << " frames (" << p.background_frames
              << " background, " << p.standstill_frames << " standstill, " << p.motion_frames
              << " motion) at " << p.fps << " fps, " << synth::ArmSideName(p.side) << " arm, "
              << (p.short_sleeves ? "short" : "long") << " sleeves, camouflage " << p.camouflage
              << " -> " << outdir << "/{scene.avi,armlength.png,background.png,truth.tsv}\n";
  }
  return kExitOk;
}

}  // namespace

int RunSynthArm(const std::vector<std::string>& args, const GlobalOptions& global) {
  synth::ArmSceneOptions o;
  std::vector<std::string> outdir;
  std::string codec = o.codec;
  bool random = false;
  std::string generator = "room";
  synth::SceneTier tier = synth::SceneTier::kMedium;
  ArgParser p(
      "synth arm",
      "  armmimic-cli synth arm OUTDIR [--seed N] [--size WxH] [--fps F]\n"
      "      [--background-frames K] [--standstill-frames M] [--frames N] [--noise S]\n"
      "      [--codec MJPG|XVID|H264] [--quality Q] [--contrast C] [--drift D] [--shadow]\n"
      "      [--head-motion] [--motion swing|bend|yaw|mixed] [--side left|right]\n"
      "  armmimic-cli synth arm OUTDIR --random [--tier easy|medium|hard] [--seed N] [--size WxH]\n"
      "  armmimic-cli synth arm OUTDIR --generator capsule [--tier medium|hard] [--seed N]\n"
      "      [--size WxH]",
      "Renders a person in a room following the thesis protocol: K frames of the empty scene,\n"
      "M standstill frames with both arms hanging, then N frames of one arm moving with known\n"
      "upper-arm and forearm directions. Writes OUTDIR/scene.avi, armlength.png (the moving arm\n"
      "straight and horizontal, thesis 5.2.3), background.png (the empty scene) and truth.tsv.\n"
      "OUTDIR is created if missing. The same seed and options give the same files.\n"
      "With --random the seed and the tier draw the whole scene (the person's place, size,\n"
      "proportions and clothing, the room and its furniture, the camera, the light, the frame\n"
      "rate and the motion; docs/synth.md); only --seed and --size go with it. Seeds " +
          std::to_string(synth::kTuningSeedFirst) + "-" + std::to_string(synth::kTuningSeedLast) +
          "\nare for tuning, seeds " + std::to_string(synth::kHeldOutSeedFirst) + "-" +
          std::to_string(synth::kHeldOutSeedLast) +
          " are held out for measurement only.\n"
          "--generator capsule draws a person of shaded 3-D capsules under a perspective camera\n"
          "instead (a second generator, docs/synth.md); tuning seeds " +
          std::to_string(synth::kCapsuleTuningSeedFirst) + "-" +
          std::to_string(synth::kCapsuleTuningSeedLast) + ", held out " +
          std::to_string(synth::kCapsuleHeldOutSeedFirst) + "-" +
          std::to_string(synth::kCapsuleHeldOutSeedLast) + ".");
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
  p.Flag("--random", &random, "draw the whole scene from the seed and the tier (docs/synth.md)");
  p.Custom("--generator", "NAME",
           "room (default: the fixed room), random (as --random) or capsule (3-D capsules)",
           [&generator](const std::string& v) -> std::string {
             if (v != "room" && v != "random" && v != "capsule") {
               return "'" + v + "' is not room, random or capsule";
             }
             generator = v;
             return "";
           });
  p.Custom("--tier", "TIER", "with --random: easy, medium (default) or hard; capsule: medium, hard",
           [&tier](const std::string& v) -> std::string {
             if (!synth::ParseSceneTier(v, &tier)) return "'" + v + "' is not easy, medium or hard";
             return "";
           });
  if (auto code = p.Parse(args)) return *code;
  if (random && generator != "room" && generator != "random") {
    return p.UsageError("--random cannot be combined with --generator " + generator);
  }
  random = random || generator == "random";
  const bool capsule = generator == "capsule";
  if (p.Given("--tier") && !random && !capsule) {
    return p.UsageError("--tier goes with --random or --generator capsule");
  }
  if (capsule) {
    for (const char* flag : kDrawnFlags) {
      if (p.Given(flag)) {
        return p.UsageError(std::string(flag) +
                            " cannot be combined with --generator capsule: the seed draws it");
      }
    }
    if (tier == synth::SceneTier::kEasy) {
      return p.UsageError("--tier easy: capsule scenes have the tiers medium and hard");
    }
    synth::CapsuleArmSceneOptions co;
    co.seed = o.seed;
    co.tier = tier;
    co.size = o.size;
    if (Status st = co.Check(); !st.ok()) return p.UsageError(Worded(st));
    return WriteCapsuleScene(co, outdir[0], global);
  }
  if (random) {
    for (const char* flag : kDrawnFlags) {
      if (p.Given(flag)) {
        return p.UsageError(std::string(flag) +
                            " cannot be combined with --random: the seed draws it");
      }
    }
    synth::RandomArmSceneOptions ro;
    ro.seed = o.seed;
    ro.tier = tier;
    ro.size = o.size;
    if (Status st = ro.Check(); !st.ok()) return p.UsageError(Worded(st));
    return WriteRandom(ro, outdir[0], global);
  }
  for (char& c : codec) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (codec == "AVC1" || codec == "X264") codec = "H264";
  o.codec = codec;
  if (Status st = o.Check(); !st.ok()) return p.UsageError(Worded(st));

  if (const int code = WriteSceneWithProgress(
          "arm", o.frame_count(), global,
          [&](const auto& progress, const auto* cancel) {
            return synth::WriteArmScene(o, outdir[0], progress, cancel);
          },
          outdir[0] + " unchanged (the scene is written whole or not at all)");
      code != kExitOk) {
    return code;
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
