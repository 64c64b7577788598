// One place for the CLI's key -> flag words, until the flags are registered from the option
// tables and ArgParser can answer it from its own options.
#include "flag_for_key.h"

#include <map>

namespace armmimic::cli {

std::string FlagForKey(const std::string& key) {
  static const std::map<std::string, std::string> flags = {
      // The analysis inputs (AnalysisOptions).
      {"analysis.engine", "--engine"},
      {"analysis.background", "--background"},
      {"analysis.background_frames", "--background-frames"},
      {"analysis.arm_length", "--arm-length"},
      {"analysis.reference", "--reference"},
      {"analysis.start", "--start"},
      {"analysis.shoulder", "--shoulder"},
      {"analysis.elbow", "--elbow"},
      {"analysis.wrist", "--wrist"},
      {"analysis.roi", "--roi"},
      {"analysis.model", "--model"},
      {"analysis.auto_calibrate", "--auto-calibrate"},
      {"analysis.side", "--side"},
      // Engine parameters with a flag of their own; the others go through --param.
      {"bgsub.threshold", "--threshold"},
      {"bgsub.background_frames", "--background-frames"},
      {"bgsub.standstill_frames", "--standstill-frames"},
      {"bgsub.thesis_mode", "--thesis"},
      {"lk.standstill_frames", "--standstill-frames"},
      {"lk.initial_upper_deg", "--initial-upper"},
      {"lk.initial_fore_deg", "--initial-fore"},
      {"lk.thesis_mode", "--thesis"},
      {"marker.low", "--low"},
      {"marker.high", "--high"},
      {"marker.fov_deg", "--fov"},
      {"marker.thesis_mode", "--thesis"},
      {"pose.side", "--side"},
      // Planner, mapping and limits (plan, mimic).
      {"planner.cutoff_hz", "--cutoff"},
      {"planner.max_gap_s", "--max-gap-s"},
      {"planner.max_jump_deg_s", "--max-jump"},
      {"planner.deadband_deg", "--deadband"},
      {"planner.min_interval_s", "--min-interval"},
      {"planner.max_interval_s", "--max-interval"},
      {"planner.fallback_fps", "--fallback-fps"},
      {"mapping.j1", "--map-j1"},
      {"mapping.j2", "--map-j2"},
      {"mapping.j3", "--map-j3"},
      {"mapping.hold_deg", "--hold"},
      {"limits.min_deg", "--limits"},
      {"limits.max_deg", "--limits"},
      {"limits.max_speed_deg_s", "--speed-limit"},
      // The serial port and the send's starting point (send, mimic).
      {"port.port", "--port"},
      {"port.baud", "--baud"},
      {"port.data_bits", "--data-bits"},
      {"port.parity", "--parity"},
      {"port.stop_bits", "--stop-bits"},
      {"port.flow", "--flow"},
      {"send.mode", "--resume/--restart"},
      {"send.resume", "--resume"},
      {"send.resume_at_line", "--resume-at"},
      {"sim.link", "--link"},
      // Scene generators (synth arm, synth marker).
      {"arm_scene.size", "--size"},
      {"arm_scene.fps", "--fps"},
      {"arm_scene.background_frames", "--background-frames"},
      {"arm_scene.standstill_frames", "--standstill-frames"},
      {"arm_scene.motion_frames", "--frames"},
      {"arm_scene.noise_sigma", "--noise"},
      {"arm_scene.codec", "--codec"},
      {"arm_scene.jpeg_quality", "--quality"},
      {"arm_scene.clothing_contrast", "--contrast"},
      {"arm_scene.lighting_drift", "--drift"},
      {"marker_scene.size", "--size"},
      {"marker_scene.views", "--views"},
      {"marker_scene.max_yaw_deg", "--max-yaw"},
      {"marker_scene.max_bend_deg", "--max-bend"},
      {"marker_scene.noise_sigma", "--noise"},
      {"marker_scene.background", "--background"},
      {"marker_scene.lighting", "--lighting"},
      {"marker_scene.clutter", "--clutter"},
      {"marker_scene.camera", "--camera"},
      {"marker_scene.fov_deg", "--fov"},
  };
  const auto it = flags.find(key);
  if (it != flags.end()) return it->second;
  for (const char* engine : {"bgsub.", "lk.", "marker.", "pose."}) {
    if (key.rfind(engine, 0) == 0) return "--param " + key;
  }
  return std::string();
}

std::string Worded(const Status& status) {
  const std::string flag = FlagForKey(status.key());
  return flag.empty() ? status.message() : flag + ": " + status.message();
}

}  // namespace armmimic::cli
