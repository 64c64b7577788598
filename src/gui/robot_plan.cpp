#include "robot_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include "armmimic/robot/mapping.h"
#include "armmimic/robot/val_program.h"

namespace armmimic::gui {

Status RobotPlan::Load(const std::string& path) {
  Clear();
  AngleFile file;
  const Status st = ReadAngleFile(path, &file);
  if (!st) return st;
  angles_ = std::move(file);
  path_ = path;
  loaded_ = true;
  return Status::Ok();
}

Status RobotPlan::LoadProgram(const std::string& path, const robot::ControllerProfile& profile) {
  Clear();
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::Error(path + ": cannot open the VAL program");
  std::ostringstream text;
  text << in.rdbuf();
  std::istringstream lines(text.str());
  robot::ValProgram program;
  Status st = robot::ParseValProgram(lines, path, profile.max_line_length, &program);
  if (!st) return st;
  // The motion lines as keyframes, for the preview: "[DO] MOVE #PPOINT(j1,...,j6)".
  static const std::regex kMove(R"(^\s*(?:DO\s+)?MO\w*\s+#PPOINT\(([^)]*)\))", std::regex::icase);
  double t = 0;
  for (const robot::ValLine& line : program.lines) {
    std::smatch m;
    if (!std::regex_search(line.text, m, kMove)) continue;
    robot::Keyframe k;
    std::istringstream values(m[1].str());
    std::string value;
    int j = 0;
    while (j < robot::kJoints && std::getline(values, value, ','))
      k.joint_deg[j++] = std::atof(value.c_str());
    if (j != robot::kJoints) continue;
    t = std::isfinite(line.time_s) ? line.time_s : t + 1.0;
    k.time_s = t;
    program_trajectory_.keyframes.push_back(k);
  }
  program_ = std::move(program);
  program_text_ = text.str();
  path_ = path;
  return Status::Ok();
}

void RobotPlan::Clear() {
  loaded_ = planned_ = false;
  program_.reset();
  program_text_.clear();
  program_trajectory_ = robot::Trajectory();
  path_.clear();
  angles_ = AngleFile();
  trajectory_ = robot::Trajectory();
  report_ = robot::PlanReport();
}

Status RobotPlan::Plan(const robot::PlannerOptions& options) {
  planned_ = false;
  if (program_) return CheckProgram(options);
  if (!loaded_) return Status::Error("no angle file: run the analysis first");
  options_ = options;
  trajectory_ = robot::Trajectory();
  report_ = robot::PlanReport();
  const Status st = robot::PlanTrajectory(angles_, options_, &trajectory_, &report_);
  // Named by what the operator analysed: the angle file itself is a temporary one.
  if (!st) {
    return Status::Error(st.key(),
                         "the analysis of " + angles_.Meta("source", "?") + ": " + st.message());
  }
  planned_ = true;
  return Status::Ok();
}

// A program from a file is sent as written: "planning" it is the safety check every line gets
// again on its way out, against the limits shown and those its header records.
Status RobotPlan::CheckProgram(const robot::PlannerOptions& options) {
  options_ = options;
  trajectory_ = program_trajectory_;
  report_ = robot::PlanReport();
  for (int j = 0; j < robot::kJoints; ++j) {
    report_.min_deg[j] = report_.max_deg[j] = trajectory_.keyframes.empty() ? 0 : NAN;
    for (const robot::Keyframe& k : trajectory_.keyframes) {
      report_.min_deg[j] = std::fmin(report_.min_deg[j], k.joint_deg[j]);
      report_.max_deg[j] = std::fmax(report_.max_deg[j], k.joint_deg[j]);
    }
  }
  robot::SafetyState safety = robot::SafetyState::For(SendLimits(), robot::ControllerProfile());
  const Status st = robot::CheckProgram(*program_, safety);
  if (!st) return st;
  planned_ = true;
  return Status::Ok();
}

robot::JointLimits RobotPlan::SendLimits() const {
  if (program_ && program_->has_header_limits) {
    return robot::JointLimits::Intersect(options_.limits, program_->header_limits);
  }
  return options_.limits;
}

bool RobotPlan::MappedPose(int frame, const robot::PlannerOptions& options,
                           robot::JointArray* out) const {
  robot::MappingOptions mapping = options.mapping;
  mapping.kind = robot::DetectSourceKind(angles_);
  // An arm file's 3-D columns turn the joints as the plan turns them (docs/robot.md).
  const int side_3d = robot::SideFor3d(mapping, mapping.kind, angles_);
  // A row whose yaw sign is unknown (or whose azimuth is blind) shows J1 where the plan holds
  // it: at the last turn known.
  double held_yaw = 0;
  for (const AngleRow& row : angles_.rows) {
    double upper = row.upper_deg, bend = row.bend_deg;
    double turn = row.turn_yaw_deg(angles_.has_signed_yaw_column);
    const bool from_3d = side_3d != 0 && robot::SourcesFrom3d(row, side_3d, &upper, &bend, &turn);
    if (row.frame != frame) {
      if (row.ok() && std::isfinite(turn)) held_yaw = turn;
      continue;
    }
    if (!row.ok() || (side_3d != 0 && !from_3d) ||
        (std::isnan(upper) && mapping.kind == robot::SourceKind::kArm)) {
      return false;
    }
    const double yaw = std::isnan(turn) ? held_yaw : turn;
    *out = mapping.Map(std::isnan(upper) ? -90.0 : upper, std::isnan(bend) ? 0.0 : bend, yaw);
    return true;
  }
  return false;
}

bool RobotPlan::PersonArmAt(int frame, const robot::PlannerOptions& options,
                            robot::PersonArm* out) const {
  const int side = robot::SideFor3d(options.mapping, robot::DetectSourceKind(angles_), angles_);
  if (side == 0) return false;
  for (const AngleRow& row : angles_.rows) {
    if (row.frame == frame) return robot::PersonArmFromRow(row, side, out);
  }
  return false;
}

std::vector<LimitViolation> RobotPlan::Violations(const robot::PlannerOptions& options) const {
  std::vector<LimitViolation> out;
  for (const AngleRow& row : angles_.rows) {
    robot::JointArray j;
    if (!MappedPose(row.frame, options, &j)) continue;
    for (int k = 0; k < robot::kJoints; ++k) {
      if (!options.limits.Inside(k, j[k])) out.push_back({row.frame, k, j[k]});
    }
  }
  return out;
}

robot::JointArray RobotPlan::PoseAt(double t) const {
  const auto& k = trajectory_.keyframes;
  if (k.empty()) return robot::JointArray{0, -90, 0, 0, 0, 0};
  if (t <= k.front().time_s) return k.front().joint_deg;
  if (t >= k.back().time_s) return k.back().joint_deg;
  auto it = std::upper_bound(k.begin(), k.end(), t,
                             [](double v, const robot::Keyframe& f) { return v < f.time_s; });
  const robot::Keyframe& b = *it;
  const robot::Keyframe& a = *(it - 1);
  const double u = b.time_s > a.time_s ? (t - a.time_s) / (b.time_s - a.time_s) : 1.0;
  robot::JointArray j;
  for (int i = 0; i < robot::kJoints; ++i) {
    j[i] = a.joint_deg[i] + u * (b.joint_deg[i] - a.joint_deg[i]);
  }
  return j;
}

int RobotPlan::KeyframeForFrame(int frame) const {
  int best = -1;
  for (std::size_t i = 0; i < trajectory_.keyframes.size(); ++i) {
    if (trajectory_.keyframes[i].frame <= frame) best = static_cast<int>(i);
  }
  return best;
}

Status RobotPlan::ValText(const robot::ControllerProfile& profile, std::string* text) const {
  if (!planned_) return Status::Error("no plan: plan the trajectory first");
  if (program_) {
    *text = program_text_;
    return Status::Ok();
  }
  return robot::FormatValProgram(
      trajectory_, profile, options_.limits,
      robot::DescribePlan(path_, angles_, options_, report_, trajectory_), text);
}

}  // namespace armmimic::gui
