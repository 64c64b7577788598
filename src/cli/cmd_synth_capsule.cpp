// armmimic-cli synth arm OUTDIR --generator capsule: a capsule scene (3-D capsules under a
// perspective camera, capsule_arm_scene.h) with its ground truth.
#include <iostream>

#include "armmimic/synth/capsule_arm_scene.h"
#include "synth_commands.h"

namespace armmimic::cli {

int WriteCapsuleScene(const synth::CapsuleArmSceneOptions& o, const std::string& outdir,
                      const GlobalOptions& global) {
  const synth::CapsuleArmScene scene(o);
  if (const int code = WriteSceneWithProgress(
          "arm", scene.frame_count(), global,
          [&](const auto& progress, const auto* cancel) {
            return synth::WriteCapsuleArmScene(o, outdir, progress, cancel);
          },
          outdir + " unchanged (the scene is written whole or not at all)");
      code != kExitOk) {
    return code;
  }
  if (!global.quiet) {
    const synth::CapsuleSceneParams& p = scene.params();
    std::cerr << "synth arm: capsule " << synth::SceneTierName(o.tier) << " scene, seed " << o.seed
              << ": " << scene.frame_count() << " frames (" << p.background_frames
              << " background, " << p.standstill_frames << " standstill, " << p.motion_frames
              << " motion) at " << p.fps << " fps, " << synth::ArmSideName(p.side) << " arm, "
              << p.sleeves << " sleeves, " << p.wall_texture << " wall -> " << outdir
              << "/{scene.avi,armlength.png,background.png,truth.tsv}\n";
  }
  return kExitOk;
}

}  // namespace armmimic::cli
