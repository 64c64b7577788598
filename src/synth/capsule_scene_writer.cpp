// A capsule scene's truth (with the arm's 3-D directions as extra columns), its meta line and
// its scene folder.
#include <algorithm>
#include <cmath>

#include "armmimic/core/angles.h"
#include "armmimic/synth/capsule_arm_scene.h"

namespace armmimic::synth {
namespace {

// Azimuth and elevation of a camera-frame direction (the angle file's 3-D columns).
void AzEl(const cv::Vec3d& d, double* az, double* el) {
  *az = DegFromRad(std::atan2(-d[2], d[0]));
  *el = DegFromRad(std::atan2(-d[1], std::hypot(d[0], d[2])));
}

}  // namespace

const std::array<const char*, 5>& CapsuleExtraColumns() {
  static const std::array<const char*, 5> names = {"upper_az_deg", "upper_el_deg", "fore_az_deg",
                                                   "fore_el_deg", "elbow_deg"};
  return names;
}

std::array<double, 5> CapsuleArmScene::Extras(int frame) const {
  std::array<double, 5> out;
  out.fill(kNaN);
  if (!Truth(frame).person) return out;
  const CapsuleJoints3d j = Joints3d(frame);
  const cv::Vec3d u = j.elbow - j.shoulder, f = j.wrist - j.elbow;
  AzEl(u, &out[0], &out[1]);
  AzEl(f, &out[2], &out[3]);
  const double c = (-u).dot(f) / (cv::norm(u) * cv::norm(f));
  out[4] = DegFromRad(std::acos(std::clamp(c, -1.0, 1.0)));
  return out;
}

AngleMeta CapsuleSceneMeta(const CapsuleArmScene& scene) {
  const CapsuleArmSceneOptions& o = scene.options();
  AngleMeta meta = {{"scene", "arm"},
                    {"generator", "capsule"},
                    {"seed", std::to_string(o.seed)},
                    {"tier", SceneTierName(o.tier)},
                    {"width", std::to_string(o.size.width)},
                    {"height", std::to_string(o.size.height)}};
  for (const auto& kv : scene.params().Describe()) meta.push_back(kv);
  meta.emplace_back("codec", "MJPG");
  meta.emplace_back("upper_length_px", FormatNumber(scene.upper_length_px(), 2));
  meta.emplace_back("fore_length_px", FormatNumber(scene.fore_length_px(), 2));
  return meta;
}

Status WriteCapsuleArmScene(const CapsuleArmSceneOptions& options, const std::string& outdir,
                            const std::function<void(int, int)>& progress,
                            const std::atomic<bool>* cancel) {
  if (Status st = options.Check(); !st.ok()) return st;
  const CapsuleArmScene scene(options);
  TruthFile truth;
  truth.meta = CapsuleSceneMeta(scene);
  for (const char* name : CapsuleExtraColumns()) truth.extra_columns.emplace_back(name);
  for (int f = 0; f < scene.frame_count(); ++f) {
    TruthRow row = scene.Truth(f).ToRow();
    for (double v : scene.Extras(f)) row.extra.push_back(FormatNumber(v, 3));
    truth.rows.push_back(std::move(row));
  }
  return WriteSceneFolder(scene, {"MJPG", scene.params().jpeg_quality}, truth, outdir, progress,
                          cancel);
}

}  // namespace armmimic::synth
