// A small arm scene for the CLI tests: 160x120, 10 empty, 10 standstill and `motion_frames`
// moving frames (scene.avi, background.png, armlength.png, truth.tsv), rendered once per seed
// and kept until the test program exits.
#pragma once

#include <map>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "armmimic/synth/arm_scene.h"
#include "test_util.h"

namespace armmimic::test {

inline const std::string& SmallScene(std::uint64_t seed, int motion_frames) {
  // Removed at exit with the map.
  static std::map<std::pair<std::uint64_t, int>, std::unique_ptr<TempDir>> scenes;
  std::unique_ptr<TempDir>& dir = scenes[{seed, motion_frames}];
  if (!dir) {
    dir = std::make_unique<TempDir>();
    synth::ArmSceneOptions so;
    so.seed = seed;
    so.size = {160, 120};
    so.background_frames = 10;
    so.standstill_frames = 10;
    so.motion_frames = motion_frames;
    const Status st = synth::WriteArmScene(so, dir->path(), {});
    if (!st.ok()) ADD_FAILURE() << st.message();
  }
  return dir->path();
}

}  // namespace armmimic::test
