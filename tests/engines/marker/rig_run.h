// Runs the marker-joint engine on views of the rig renderer (`synth marker --renderer rig`) and
// tallies its errors against the truth: shared by the rig accuracy and reference tests.
#pragma once

#include <cstdint>
#include <string>

#include <memory>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"
#include "armmimic/engines/engine.h"
#include "armmimic/synth/marker_rig.h"

namespace armmimic {

struct RigTally {
  int views = 0, ok = 0, bends = 0, signed_off = 0, unsigned_rows = 0;
  double yaw_sum = 0, bend_sum = 0, yaw_max = 0, bend_max = 0;
  std::string log;
  double yaw_mae() const;
  double bend_mae() const;
};

// A marker engine told the rig's field of view (as an operator who knows the lens would), begun
// on the rig's reference.
Status BeginOnRig(const synth::MarkerRigRenderer& rig, std::unique_ptr<Engine>* engine);

// Renders `views` views of the rig of `seed` in `set` (yaw and bend in +-60), runs the engine
// with the rig's field of view and tallies the errors; `described`: the begun engine's meta.
void RunRig(const std::string& set, uint64_t seed, int views, RigTally* t,
            AngleMeta* described = nullptr);

// Four views of one rig, every one answered within `yaw_max` degrees of |yaw| and none with a
// signed yaw more than 5 degrees off.
void ExpectEveryViewWithin(const std::string& set, uint64_t seed, double yaw_max);

}  // namespace armmimic
