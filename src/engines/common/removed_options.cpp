#include "armmimic/engines/removed_options.h"

namespace armmimic {

const std::vector<RemovedEngineOption>& RemovedEngineOptions() {
  // bgsub: the blob path's improvements were read only by its blob picking and hull analysis,
  // which the default path replaced with a per-pixel model and a two-segment fit; the thesis
  // path never read them. background_frames was never read by the engine at all.
  static const std::vector<RemovedEngineOption> removed = {
      {"bgsub.background_frames",
       "never read by the engine: the run's own background_frames sets how many frames make the "
       "background"},
      {"bgsub.compensate_drift", "replaced by the per-pixel model's light matching"},
      {"bgsub.color_difference", "replaced by the per-pixel model's colour comparison"},
      {"bgsub.reject_shadow",
       "replaced by the per-pixel model's light matching and the fit's confidence"},
      {"bgsub.reject_head", "replaced by the two-segment fit from the calibrated shoulder"},
      {"bgsub.near_shoulder", "replaced by the two-segment fit from the calibrated shoulder"},
      {"bgsub.two_line_split", "replaced by the two-segment fit"},
      {"bgsub.extent_yaw", "replaced by the two-segment fit, whose straight arm has yaw 0"},
      {"bgsub.bend_hysteresis", "replaced by the two-segment fit's bend"},
      {"bgsub.shoulder_from_arm_length",
       "replaced by the calibration, which always places the shoulder from the arm-length image"},
      {"bgsub.rest_pose", "replaced by bgsub.rest_deg: the rows always start at the rest pose"},
      {"bgsub.upper_from_person", "replaced by the two-segment fit's evidence weights"},
  };
  return removed;
}

const RemovedEngineOption* FindRemovedEngineOption(const std::string& key) {
  for (const RemovedEngineOption& r : RemovedEngineOptions()) {
    if (key == r.key) return &r;
  }
  return nullptr;
}

Status RemovedEngineOptionError(const RemovedEngineOption& removed) {
  return Status::Error(removed.key, std::string(removed.key) +
                                        " was removed: the default path no longer read it (" +
                                        removed.replaced_by + ")");
}

std::string DescribeIgnoredEngineOptions(const std::vector<std::string>& keys) {
  if (keys.empty()) return "";
  std::string what;
  for (const std::string& key : keys) {
    const RemovedEngineOption* r = FindRemovedEngineOption(key);
    what += (what.empty() ? "" : "; ") + key + (r ? std::string(": ") + r->replaced_by : "");
  }
  return "ignored " + std::to_string(keys.size()) + " recorded setting" +
         (keys.size() == 1 ? "" : "s") + ", removed: the default path no longer reads " +
         (keys.size() == 1 ? "it" : "them") + " (" + what + ")";
}

}  // namespace armmimic
