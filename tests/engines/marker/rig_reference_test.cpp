// The marker-joint engine's reference taken as a camera other than the model's would show it, on
// the rig renderer (`synth marker --renderer rig`): a tilted camera levelled (docs/marker.md,
// calibration step 6), a limb only one colour channel shows (step 7), and colour channels that
// disagree refusing the reference.
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"
#include "armmimic/engines/engine.h"
#include "armmimic/synth/marker_rig.h"
#include "marker/rig_run.h"

namespace armmimic {
namespace {

// A camera tilted 4-7 degrees (tuning hard 222 and medium 107, validation medium 151): the
// model's camera is level, so the bent upper part's marker was placed a pixel or more off and
// the bends came out 1.0-2.6 degrees off on average. The reference's two limbs lean apart by the
// tilt; it is read from them (within a degree of the rig's), and the reference and every view
// are levelled before the model sees them.
TEST(MarkerRigAccuracy, ATiltedCameraIsLevelled) {
  RigTally t;
  const std::pair<const char*, uint64_t> rigs[] = {{"hard", 222}, {"medium", 107}, {"medium", 151}};
  for (const auto& [set, seed] : rigs) {
    AngleMeta meta;
    RunRig(set, seed, 4, &t, &meta);
    const double pitch = std::stod(MetaValue(meta, "camera_pitch_deg", "0"));  // 0: not levelled
    synth::MarkerRigOptions o;
    o.set = set;
    o.seed = seed;
    EXPECT_NEAR(pitch, synth::MarkerRigRenderer(o).rig().pitch_deg, 1.0) << set << " " << seed;
  }
  EXPECT_EQ(t.ok, 12) << t.log;
  EXPECT_LE(t.yaw_mae(), 0.5) << t.log;
  EXPECT_LE(t.bend_mae(), 0.6) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// Validation medium 148 and hard 248: the luma image shows a limb too faintly to place it (the
// surface shaded to the wall's grey), and the reference was refused; one colour channel alone
// shows it, and the views are measured in that channel (docs/marker.md, calibration step 7).
TEST(MarkerRigAccuracy, ALimbTheLumaDoesNotShowIsFoundInOneColourChannel) {
  RigTally t;
  for (const auto& [set, seed] : {std::pair<const char*, uint64_t>{"medium", 148}, {"hard", 248}}) {
    AngleMeta meta;
    RunRig(set, seed, 4, &t, &meta);
    EXPECT_NE(MetaValue(meta, "channel", "luma"), "luma") << set << " " << seed;
  }
  EXPECT_GE(t.ok, 6) << t.log;
  EXPECT_LE(t.yaw_mae(), 0.5) << t.log;
  EXPECT_LE(t.bend_mae(), 1.0) << t.log;
  EXPECT_EQ(t.signed_off, 0) << t.log;
}

// What the calibration chose that the operator did not give (validation medium 148: a camera
// tilted 5.3 degrees up, a limb only a colour channel shows) is told once, with the first view.
TEST(MarkerRigAccuracy, TheCalibrationsChoicesAreToldWithTheFirstView) {
  synth::MarkerRigOptions o;
  o.set = "medium";
  o.seed = 148;
  o.views = 2;
  const synth::MarkerRigRenderer rig(o);
  std::unique_ptr<Engine> engine;
  ASSERT_TRUE(BeginOnRig(rig, &engine).ok());
  const std::string channel = MetaValue(engine->Describe(), "channel", "luma");
  std::vector<std::string> told;
  for (int i = 0; i < o.views; ++i) {
    Frame frame;
    frame.image = rig.Render(i);
    frame.index = i;
    told.push_back(engine->Process(frame).estimate);
  }
  EXPECT_NE(told[0].find("degrees up"), std::string::npos) << told[0];
  EXPECT_NE(told[0].find("only in its " + channel + " channel"), std::string::npos) << told[0];
  EXPECT_EQ(told[1], "");
}

// Tuning hard 215: the luma refuses the reference, and the red, green and blue channels each
// calibrate it, with marker angles 5-11 degrees apart (the blue one took a green wall bar beside
// a limb for the limb, and read a view 6 degrees off): channels that disagree refuse it.
TEST(MarkerRigAccuracy, ColourChannelsThatPlaceTheLimbsApartRefuseTheReference) {
  synth::MarkerRigOptions o;
  o.set = "hard";
  o.seed = 215;
  o.views = 1;
  std::unique_ptr<Engine> engine;
  const Status begun = BeginOnRig(synth::MarkerRigRenderer(o), &engine);
  EXPECT_FALSE(begun.ok());
  EXPECT_NE(begun.message().find("dark patches across the joint"), std::string::npos)
      << begun.message();
  // ... and says that the colour channels were tried, and why they did not help.
  EXPECT_NE(begun.message().find("single colour channels calibrate it"), std::string::npos)
      << begun.message();
  EXPECT_NE(begun.message().find("which disagree"), std::string::npos) << begun.message();
}

}  // namespace
}  // namespace armmimic
