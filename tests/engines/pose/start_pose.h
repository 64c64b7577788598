// The pose engine made and begun on frames of `size` with `side` (either network, per `pose`),
// for the pose tests; a Begin() that fails is a test failure.
#pragma once

#include <memory>

#include <gtest/gtest.h>

#include "armmimic/engines/engine.h"
#include "armmimic/engines/pose.h"

namespace armmimic::test {

inline std::unique_ptr<Engine> StartPose(const cv::Size& size, PoseSide side,
                                         const PoseOptions& pose = PoseOptions()) {
  EngineOptions o;
  o.kind = EngineKind::kPose;
  o.pose = pose;
  o.pose.side = side;
  auto engine = Engine::Create(o);
  EngineContext context;
  context.frame_size = size;
  context.fps = 30;
  const Status st = engine->Begin(context);
  EXPECT_TRUE(st.ok()) << st.message();
  return engine;
}

}  // namespace armmimic::test
