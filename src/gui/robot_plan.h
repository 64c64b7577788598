// RobotPlan: the angle file of the last analysis turned into a PUMA trajectory with the
// planner's options (the same PlannerOptions `armmimic-cli plan` fills), the .val text, and the
// frames whose mapped pose falls outside the joint limits, found before anything moves.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/status.h"
#include "armmimic/robot/kinematics.h"
#include "armmimic/robot/planner.h"
#include "armmimic/robot/profile.h"
#include "armmimic/robot/trajectory.h"
#include "armmimic/robot/val_program.h"

namespace armmimic::gui {

struct LimitViolation {
  int frame = 0;
  int joint = 0;  // 0-based
  double deg = 0;
};

class RobotPlan {
 public:
  // Reads the angle file; the mapping kind follows the file (arm or marker).
  Status Load(const std::string& angle_path);
  // Reads a VAL program (a .val from `plan` or an earlier export) to send as it is written;
  // Plan() then checks it line by line against the limits instead of planning.
  Status LoadProgram(const std::string& path, const robot::ControllerProfile& profile);
  bool fromProgram() const { return program_.has_value(); }
  // The limits a send is checked against: those shown, narrowed by a program's header.
  robot::JointLimits SendLimits() const;
  void Clear();
  bool loaded() const { return loaded_; }
  const AngleFile& angles() const { return angles_; }
  const std::string& angle_path() const { return path_; }  // or the program's path

  // Plans with `options` (its mapping kind is set from the file). Fills trajectory and report.
  Status Plan(const robot::PlannerOptions& options);
  bool planned() const { return planned_; }
  const robot::Trajectory& trajectory() const { return trajectory_; }
  const robot::PlanReport& report() const { return report_; }
  const robot::PlannerOptions& options() const { return options_; }

  // Every row mapped without filtering or clamping, checked against the limits.
  std::vector<LimitViolation> Violations(const robot::PlannerOptions& options) const;
  // The mapped joints of a row (NaN yaw held at 0), for the preview at the video's frame.
  bool MappedPose(int frame, const robot::PlannerOptions& options, robot::JointArray* out) const;
  // The person's arm at `frame` from the file's 3-D columns, as the 3-D view draws it beside the
  // robot; false where the row lacks them or the mapping plans from the 2-D columns.
  bool PersonArmAt(int frame, const robot::PlannerOptions& options, robot::PersonArm* out) const;
  // The pose of the trajectory at time t (linear between keyframes).
  robot::JointArray PoseAt(double t_s) const;
  // Index of the keyframe at or before the angle file's `frame` (-1: none).
  int KeyframeForFrame(int frame) const;

  // The .val program text for the current trajectory (a loaded program: its text as read).
  Status ValText(const robot::ControllerProfile& profile, std::string* text) const;

 private:
  Status CheckProgram(const robot::PlannerOptions& options);

  bool loaded_ = false;
  bool planned_ = false;
  std::optional<robot::ValProgram> program_;
  std::string program_text_;
  robot::Trajectory program_trajectory_;
  std::string path_;
  AngleFile angles_;
  robot::PlannerOptions options_;
  robot::Trajectory trajectory_;
  robot::PlanReport report_;
};

}  // namespace armmimic::gui
