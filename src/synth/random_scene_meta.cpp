// A random scene's knobs as key=value pairs (the truth file's meta line, the benchmark's
// columns), and its scene folder.
#include "armmimic/synth/random_arm_scene.h"

namespace armmimic::synth {
namespace {

std::string Num(double v, int decimals) {
  std::string s = FormatNumber(v, decimals);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s;
}

const char* YesNo(bool b) { return b ? "yes" : "no"; }

}  // namespace

AngleMeta RandomSceneParams::Describe() const {
  return {{"fps", Num(fps, 3)},
          {"background_frames", std::to_string(background_frames)},
          {"standstill_frames", std::to_string(standstill_frames)},
          {"motion_frames", std::to_string(motion_frames)},
          {"side", ArmSideName(side)},
          {"arm_fraction", Num(arm_fraction, 3)},
          {"offcentre", Num(offcentre, 3)},
          {"body_width", Num(body_width, 2)},
          {"head_size", Num(head_size, 2)},
          {"neck", Num(neck, 2)},
          {"limb_thickness", Num(limb_thickness, 2)},
          {"sleeves", short_sleeves ? "short" : "long"},
          {"sleeve_cover", Num(sleeve_cover, 2)},
          {"skin_tone", Num(skin_tone, 2)},
          {"sleeve_match", sleeve_match},
          {"camouflage", camouflage},
          {"sleeve_wall_distance", Num(sleeve_wall_distance, 1)},
          {"skin_wall_distance", Num(skin_wall_distance, 1)},
          {"wall_texture", wall_texture},
          {"furniture", std::to_string(furniture)},
          {"furniture_behind_arm", YesNo(furniture_behind_arm)},
          {"vignetting", Num(vignetting, 2)},
          {"noise", Num(noise_sigma, 2)},
          {"jpeg_quality", std::to_string(jpeg_quality)},
          {"drift", Num(drift, 3)},
          {"flicker", Num(flicker, 3)},
          {"shadow", YesNo(shadow)},
          {"shadow_strength", Num(shadow_strength, 2)},
          {"sway_px", Num(sway_px, 2)},
          {"head_motion", YesNo(head_motion)},
          {"speed_limit_deg", Num(speed_limit_deg, 1)},
          {"max_step_deg", Num(max_step_deg, 2)},
          {"hand_by_head", YesNo(hand_by_head)},
          {"hand_above_head", YesNo(hand_above_head)},
          {"across_torso", YesNo(across_torso)},
          {"raised", YesNo(raised)}};
}

AngleMeta RandomSceneMeta(const RandomArmScene& scene) {
  const RandomArmSceneOptions& o = scene.options();
  AngleMeta meta = {{"scene", "arm"},
                    {"random", "1"},
                    {"seed", std::to_string(o.seed)},
                    {"tier", SceneTierName(o.tier)},
                    {"width", std::to_string(o.size.width)},
                    {"height", std::to_string(o.size.height)}};
  for (auto& kv : scene.params().Describe()) meta.push_back(std::move(kv));
  meta.emplace_back("codec", "MJPG");
  meta.emplace_back("upper_length_px", FormatNumber(scene.upper_length_px(), 2));
  meta.emplace_back("fore_length_px", FormatNumber(scene.fore_length_px(), 2));
  return meta;
}

Status WriteRandomArmScene(const RandomArmSceneOptions& options, const std::string& outdir,
                           const std::function<void(int, int)>& progress,
                           const std::atomic<bool>* cancel) {
  const Status st = options.Check();
  if (!st.ok()) return st;
  const RandomArmScene scene(options);
  return WriteSceneFolder(scene, {"MJPG", scene.params().jpeg_quality}, RandomSceneMeta(scene),
                          outdir, progress, cancel);
}

}  // namespace armmimic::synth
