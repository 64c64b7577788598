// RobotPanel: the robot side of the workflow. Mapping, limits, filter and decimation settings
// (the planner's options), the arm preview animated over the plan with limit violations shown,
// the port settings, controller profile and connection, the built-in simulated controller, and
// sending with a confirmation, progress, pause, abort, resume from the journal and the
// controller's replies. Planning is RobotPlan, the port and profile fields ControllerSettings,
// sending RobotLink (robot::SendSession), the simulator SimController: this widget only edits
// and shows. The send itself is in robot_panel_send.cpp.
#pragma once

#include <memory>

#include <QTimer>
#include <QWidget>
#include <functional>
#include <vector>

#include "armmimic/core/same_file.h"
#include "armmimic/robot/planner.h"
#include "armmimic/robot/profile.h"
#include "armmimic/robot/send_session.h"
#include "robot_plan.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QSettings;
class QTableWidget;
namespace Ui {
class RobotPanelForm;
}

namespace armmimic::gui {

class ArmView3D;
class ControllerSettings;
class RobotLink;
class RobotPreview;
class SimController;

class RobotPanel : public QWidget {
  Q_OBJECT
 public:
  explicit RobotPanel(QWidget* parent = nullptr);
  ~RobotPanel() override;

  robot::PlannerOptions plannerOptions() const;
  void setPlannerOptions(const robot::PlannerOptions& options);
  const RobotPlan& plan() const { return plan_; }
  RobotLink* link() const { return link_; }
  SimController* simulator() const { return sim_; }
  ControllerSettings* controllerSettings() const { return controller_; }
  // The controller profile picked on the Controller tab (as last read from its file).
  const robot::ControllerProfile& profile() const { return profile_; }
  RobotPreview* preview() const { return preview_; }  // the compact 2-D views
  ArmView3D* view3d() const { return view3d_; }

  void save(QSettings& settings) const;
  void load(QSettings& settings);

  bool replan();
  // Where a send writes the plan before it sends it (SESSION.val or VIDEO.val): the journal goes
  // beside it, so a later process can resume. "" when there is nowhere to write it.
  void setPlanFile(std::function<QString()> path) { plan_file_ = std::move(path); }
  // The file the current plan is sent as: that file, or the program opened from a file.
  QString planFile() const;
  // The plan shown has an unfinished send in the journal beside its file (said in Messages when
  // the plan was made from a file or a session): Resume… continues it.
  bool resumeOffered() const { return resume_offered_; }
  // Refuses (errorOccurred) a path that is the angle file or one of `inputs_` files.
  bool exportVal(const QString& path);
  // The session's files (video, images), which exportVal never replaces.
  void setInputFiles(std::function<std::vector<NamedPath>()> inputs) {
    inputs_ = std::move(inputs);
  }
  bool startSimulator(double time_scale);
  bool connectTo(const QString& device);
  // Sends the plan. `confirmed` false asks the operator first (duration, start pose, joint
  // ranges against the limits), and, when the journal shows an earlier send of the same program
  // stopped part way, whether to resume it or start over. `confirmed` true sends from the first
  // line and refuses while such a send is unfinished.
  bool sendPlan(bool confirmed);
  // Continues an interrupted send after the last line its journal shows acknowledged, with the
  // refusals of `armmimic-cli send --resume` (no journal, a journal of another program).
  bool resumeSend(bool confirmed);
  QString replyLog() const;

 public slots:
  // The angle file of the finished analysis ("" clears the plan).
  void setAngleFile(const QString& path);
  // While an analysis replaces the angles shown, the plan made from the old ones may not be
  // sent: Send and Resume stay off until setAngleFile, or until the run fails (false).
  void setAnglesChanging(bool changing);
  bool anglesChanging() const { return angles_changing_; }
  // A VAL program to send as it is written (checked against the limits first).
  bool setValProgram(const QString& path);
  void setVideoFrame(int frame);
  // Asks where to write the .val, suggesting `suggested` (default: program.val).
  void exportValInteractive(const QString& suggested = QString());
  // Every plan setting and limit back to its documented default.
  void resetPlannerDefaults();

 signals:
  void message(const QString& text);
  void errorOccurred(const QString& text);
  void linkStateChanged(const QString& text);
  void sendFinished(bool ok);
  void sendingChanged(bool sending);

 private:
  void wirePlanBox();
  void wireLinkBox();
  void showPlannerDefaults();
  void showArm(const robot::JointArray& joint_deg, const QString& caption);
  void refreshPorts();
  void updateButtons();
  void showPose();
  void followFileKind(robot::SourceKind kind);
  void setMappingKind(robot::SourceKind kind);
  bool startSend(robot::SendStart::Mode mode, bool confirmed);
  // The program the plan gives with `profile`, and the file it is sent as (its journal is
  // FILE.journal); `write` first writes a plan to that file. False: errorOccurred said why.
  bool programToSend(const robot::ControllerProfile& profile, bool write, bool confirmed,
                     robot::ValProgram* program, std::string* input);
  void offerResume();
  bool writePlanFile(const std::string& text, const QString& path, bool confirmed);
  // The panel's words for the refusals of a resume (SendSession::Prepare checks them again).
  bool checkResumable(const robot::ValProgram& program, const std::string& input);

  std::unique_ptr<Ui::RobotPanelForm> ui_;  // ui/robot_panel.ui
  RobotPlan plan_;
  std::function<std::vector<NamedPath>()> inputs_;
  std::function<QString()> plan_file_;
  robot::ControllerProfile profile_;
  RobotLink* link_;
  SimController* sim_;
  ControllerSettings* controller_;
  RobotPreview* preview_;
  ArmView3D* view3d_;
  QTimer animate_;
  QTimer sim_poll_;
  double anim_t_ = 0;
  int video_frame_ = 0;
  QString last_plan_failure_;      // noted once in Messages
  QString last_plan_failure_key_;  // the setting it is about (Status::key()), or ""
  bool angles_changing_ = false;
  bool resume_offered_ = false;
  // Plan settings.
  QLabel* source_;
  QCheckBox* mirror_;
  QLabel* map_labels_[3];
  robot::SourceKind mapping_kind_ = robot::SourceKind::kArm;  // whose defaults the rows show
  QComboBox* sign_[3];
  QDoubleSpinBox* offset_[3];
  QDoubleSpinBox* cutoff_;
  QDoubleSpinBox* deadband_;
  QDoubleSpinBox* min_interval_;
  QDoubleSpinBox* max_gap_;
  QCheckBox* clamp_;
  QTableWidget* limits_;
  robot::JointLimits shown_limits_;  // what the table's cells say, kept when a cell is not a number
  QLabel* report_;
  QPushButton* animate_button_;
  // Link.
  QComboBox* port_;
  QDoubleSpinBox* sim_speed_;
  QPushButton* sim_button_;
  QPushButton* connect_button_;
  QPushButton* send_button_;
  QPushButton* pause_button_;
  QPushButton* resume_button_;
  QPushButton* abort_button_;
  QProgressBar* send_progress_;
  QPlainTextEdit* replies_;
};

}  // namespace armmimic::gui
