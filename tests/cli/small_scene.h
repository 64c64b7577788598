// A small arm scene for the CLI tests: 160x120, 10 empty, 10 standstill and `motion_frames`
// moving frames (scene.avi, background.png, armlength.png, truth.tsv), rendered once per seed
// and kept until the last test has run (SharedTempDir).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "armmimic/synth/arm_scene.h"
#include "test_util.h"

namespace armmimic::test {

inline const std::string& SmallScene(std::uint64_t seed, int motion_frames) {
  bool created = false;
  const TempDir& dir = SharedTempDir(
      "small-scene-" + std::to_string(seed) + "-" + std::to_string(motion_frames), &created);
  if (created) {
    synth::ArmSceneOptions so;
    so.seed = seed;
    so.size = {160, 120};
    so.background_frames = 10;
    so.standstill_frames = 10;
    so.motion_frames = motion_frames;
    const Status st = synth::WriteArmScene(so, dir.path(), {});
    if (!st.ok()) ADD_FAILURE() << st.message();
  }
  return dir.path();
}

// The thesis protocol's flags for a small scene in folder `scene` (for `engine`: bgsub, or an
// engine that takes the same): its background and arm-length images, the standstill from frame
// 10 for 10 frames.
inline std::vector<std::string> SmallSceneBgsubFlags(const std::string& scene,
                                                     const std::string& engine = "bgsub") {
  return {"--engine",
          engine,
          "--background",
          scene + "/background.png",
          "--arm-length",
          scene + "/armlength.png",
          "--start",
          "10",
          "--standstill-frames",
          "10"};
}

}  // namespace armmimic::test
