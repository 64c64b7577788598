// The CLI's key -> flag words. A setting with a row in an option table takes the row's flag, so
// each flag is written once, in its table; the list below holds only the inputs and scene
// settings that have no table row.
#include "flag_for_key.h"

#include <map>
#include <vector>

#include "armmimic/engines/option_fields.h"
#include "armmimic/robot/option_tables.h"
#include "armmimic/serial/port_table.h"

namespace armmimic::cli {
namespace {

// The flag of the row `key` ("planner.cutoff_hz") in the table named `table` ("planner"), or "".
template <typename O>
std::string TableFlag(const std::vector<OptionField<O>>& fields, const std::string& table,
                      const std::string& key) {
  if (key.rfind(table + ".", 0) != 0) return std::string();
  const OptionField<O>* f = FindOptionField(fields, key.substr(table.size() + 1));
  return f ? f->flag : std::string();
}

std::string FlagFromTables(const std::string& key) {
  for (const std::string& flag : {
           TableFlag(BgsubOptionFields(), "bgsub", key),
           TableFlag(LkOptionFields(), "lk", key),
           TableFlag(MarkerOptionFields(), "marker", key),
           TableFlag(PoseOptionFields(), "pose", key),
           TableFlag(robot::PlannerOptionFields(), "planner", key),
           TableFlag(robot::MappingOptionFields(), "mapping", key),
           TableFlag(robot::LimitsOptionFields(), "limits", key),
           TableFlag(robot::SendOptionFields(), "send", key),
           TableFlag(robot::LiveStreamOptionFields(), "live", key),
           TableFlag(robot::ProfileOptionFields(), "profile", key),
           TableFlag(serial::PortOptionFields(), "port", key),
       }) {
    if (!flag.empty()) return flag;
  }
  return std::string();
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& AnalysisInputFlags() {
  static const std::vector<std::pair<std::string, std::string>> flags = {
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
      {"analysis.calibrate_side", "--side"},
  };
  return flags;
}

std::string FlagForKey(const std::string& key) {
  if (std::string flag = FlagFromTables(key); !flag.empty()) return flag;
  for (const auto& [input, flag] : AnalysisInputFlags()) {
    if (input == key) return flag;
  }
  static const std::map<std::string, std::string> flags = {
      // The send's starting point and the emulator's link.
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
      {"marker_scene.set", "--set"},
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
