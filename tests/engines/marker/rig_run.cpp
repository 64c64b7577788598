// The rig renderer's views run through the marker-joint engine and scored (rig_run.h).
#include "marker/rig_run.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "armmimic/core/angles.h"
#include "armmimic/engines/engine.h"
#include "armmimic/synth/marker_rig.h"

namespace armmimic {

double RigTally::yaw_mae() const { return ok ? yaw_sum / ok : kNaN; }
double RigTally::bend_mae() const { return bends ? bend_sum / bends : kNaN; }

Status BeginOnRig(const synth::MarkerRigRenderer& rig, std::unique_ptr<Engine>* engine) {
  EngineOptions options;
  options.kind = EngineKind::kMarker;
  options.marker.fov_deg = rig.rig().fov_deg;
  *engine = Engine::Create(options);
  EngineContext context;
  context.reference = rig.Reference();
  context.frame_size = context.reference.size();
  return (*engine)->Begin(context);
}

void RunRig(const std::string& set, uint64_t seed, int views, RigTally* t, AngleMeta* described) {
  synth::MarkerRigOptions o;
  o.set = set;
  o.seed = seed;
  o.views = views;
  const synth::MarkerRigRenderer rig(o);
  std::unique_ptr<Engine> engine;
  const Status begun = BeginOnRig(rig, &engine);
  ASSERT_TRUE(begun.ok()) << begun.message() << " (" << set << " seed " << seed << ")";
  if (described) *described = engine->Describe();
  for (int i = 0; i < views; ++i) {
    synth::MarkerTruth truth;
    Frame frame;
    frame.image = rig.Render(i, &truth);
    frame.index = i;
    frame.name = truth.file;
    const ArmMeasurement m = engine->Process(frame);
    const std::string what = set + " seed " + std::to_string(seed) + " yaw " +
                             std::to_string(truth.pose.yaw_deg) + " bend " +
                             std::to_string(truth.bend_deg) + ": " + m.note + "\n";
    ++t->views;
    if (m.phase != MeasurementPhase::kOk) {
      t->log += "lost: " + what;
      continue;
    }
    ++t->ok;
    t->yaw_sum += std::abs(m.yaw_deg - std::abs(truth.pose.yaw_deg));
    t->yaw_max = std::max(t->yaw_max, std::abs(m.yaw_deg - std::abs(truth.pose.yaw_deg)));
    if (std::isnan(m.yaw_signed_deg)) {
      ++t->unsigned_rows;
    } else {
      EXPECT_DOUBLE_EQ(m.yaw_deg, std::abs(m.yaw_signed_deg));
      if (std::abs(AngleDiff(m.yaw_signed_deg, truth.pose.yaw_deg)) > 5) {
        ++t->signed_off, t->log += "signed yaw " + std::to_string(m.yaw_signed_deg) + ": " + what;
      }
    }
    if (std::isfinite(m.bend_deg)) {
      t->bend_sum += std::abs(AngleDiff(m.bend_deg, truth.bend_deg));
      t->bend_max = std::max(t->bend_max, std::abs(AngleDiff(m.bend_deg, truth.bend_deg)));
      ++t->bends;
    }
  }
}

void ExpectEveryViewWithin(const std::string& set, uint64_t seed, double yaw_max) {
  RigTally t;
  RunRig(set, seed, 4, &t);
  EXPECT_EQ(t.ok, 4) << t.log;
  EXPECT_LE(t.yaw_max, yaw_max) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

}  // namespace armmimic
