// MimicController: the logic of the "Mimic live" mode, without widgets. It runs live::MimicRun
// (the same live mimicking as `armmimic-cli mimic`) over the robot panel's serial link, with the
// Analysis panel's engine options and the Robot panel's mapping and limits. Nothing starts until
// the operator has confirmed the mapping and limits; with the dead-man on, commands go out only
// while the hold control is pressed. The panel shows what it reports: each analysed frame with
// its measurement, the planned (filtered, limited) target, the commands and the latency.
#pragma once

#include <memory>

#include <QImage>
#include <QObject>
#include <QString>
#include <QTemporaryDir>

#include "armmimic/engines/analysis.h"
#include "armmimic/robot/limits.h"
#include "armmimic/robot/planner.h"
#include "armmimic/robot/profile.h"

namespace armmimic::live {
class MimicRun;
}
namespace armmimic::serial {
class SerialLink;
}

namespace armmimic::gui {

class MimicController : public QObject {
  Q_OBJECT
 public:
  explicit MimicController(QObject* parent = nullptr);
  ~MimicController() override;

  // The operator confirmed these mapping and limits (the panel unconfirms when they change).
  void setConfirmed(bool confirmed);
  bool confirmed() const { return confirmed_; }
  // Dead-man: with it on, the robot moves only while setPressed(true).
  void setDeadman(bool on);
  bool deadman() const { return deadman_; }
  void setPressed(bool pressed);

  // Starts mimicking `analysis` (a video is paced at its frame rate) over `link` (open, not
  // sending; `device` names it in the journal). Returns false, with error(), when it cannot.
  bool start(AnalysisOptions analysis, const robot::PlannerOptions& planner,
             const robot::ControllerProfile& profile, serial::SerialLink* link,
             const QString& device);
  // Stops: no new command; the one in flight is acknowledged. A second stop abandons it.
  void stop(const QString& reason);
  bool running() const;
  // The angle file, journal and latency log of the last run ("" before the first).
  QString anglesPath() const { return angles_path_; }
  QString latencyText() const;

 signals:
  // On the GUI thread, for every analysed frame (at most one waiting at a time).
  void frameReady(const QImage& image, int index, const armmimic::ArmMeasurement& m);
  // The planner's target after each frame, and why the robot holds ("" when it follows).
  void planned(bool has_target, const robot::JointArray& target, const QString& hold);
  void commandWritten(const robot::JointArray& target);
  void latencyChanged(const QString& text);
  void runningChanged(bool running);
  void finished(bool ok, const QString& message);
  void error(const QString& message);

 private:
  void applyHold();

  // The session's folder is declared first so that it is removed last: the run, whose thread
  // may still be writing its angle file there, is stopped and joined before the folder goes.
  QTemporaryDir session_;
  std::unique_ptr<live::MimicRun> run_;
  QString angles_path_;
  int runs_ = 0;
  bool confirmed_ = false;
  bool deadman_ = false;
  bool pressed_ = false;
  std::shared_ptr<std::atomic<bool>> frame_pending_;
};

}  // namespace armmimic::gui
