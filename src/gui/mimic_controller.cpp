#include "mimic_controller.h"

#include <QDir>
#include <QMetaObject>

#include "analysis_job.h"  // the metatype of ArmMeasurement
#include "armmimic/core/angle_file.h"
#include "armmimic/live/mimic_run.h"
#include "armmimic/robot/live_log.h"
#include "armmimic/serial/serial_link.h"
#include "video_player.h"

namespace armmimic::gui {

MimicController::MimicController(QObject* parent)
    : QObject(parent), frame_pending_(std::make_shared<std::atomic<bool>>(false)) {
  qRegisterMetaType<armmimic::ArmMeasurement>();
}

MimicController::~MimicController() = default;

bool MimicController::running() const { return run_ && run_->running(); }

void MimicController::setConfirmed(bool confirmed) {
  confirmed_ = confirmed;
  if (!confirmed && running()) stop(tr("the mapping and limits are no longer confirmed"));
}

void MimicController::setDeadman(bool on) {
  deadman_ = on;
  applyHold();
}

void MimicController::setPressed(bool pressed) {
  pressed_ = pressed;
  applyHold();
}

void MimicController::applyHold() {
  if (run_) run_->SetHeld(deadman_ && !pressed_);
}

bool MimicController::start(AnalysisOptions analysis, const robot::PlannerOptions& planner,
                            const robot::ControllerProfile& profile, serial::SerialLink* link,
                            const QString& device) {
  if (running()) return false;
  if (!confirmed_) {
    emit error(tr("Mimic live: confirm the mapping and the limits first; nothing moves before"));
    return false;
  }
  if (!link || !link->is_open()) {
    emit error(
        tr("Mimic live: not connected: connect the robot (or start the simulated "
           "controller) in the Robot panel first"));
    return false;
  }
  if (!session_.isValid()) {
    emit error(tr("Mimic live: cannot create a temporary folder: %1").arg(session_.errorString()));
    return false;
  }
  // Every input is opened and checked before the controller is woken up (docs/live.md).
  if (const Status checked = CheckAnalysisInputs(analysis); !checked) {
    emit error(tr("Mimic live: %1").arg(QString::fromStdString(checked.message())));
    return false;
  }
  angles_path_ = QDir(session_.path()).filePath(QString("mimic-%1.tsv").arg(++runs_));
  live::MimicOptions o;
  o.analysis = std::move(analysis);
  o.analysis.realtime = true;  // a file is read at its own frame rate, as a camera delivers it
  o.angles_path = angles_path_.toStdString();
  o.stream.planner = planner;
  o.stream.profile = profile;
  o.stream.kind = o.analysis.engine.kind == EngineKind::kMarker ? robot::SourceKind::kMarker
                                                                : robot::SourceKind::kArm;
  o.stream.planner.mapping.follow_file_kind = true;
  o.stream.source_name = o.analysis.inputs.empty() ? "" : o.analysis.inputs.front();
  o.stream.port_name = device.toStdString();
  o.stream.journal_path = robot::LiveJournal::PathFor(o.angles_path);
  o.stream.latency_path = robot::LatencyLog::PathFor(o.angles_path);
  link->SetLinkSettings(robot::LinkSettings::FromProfile(profile));

  run_.reset();
  run_ = std::make_unique<live::MimicRun>(link);
  auto pending = frame_pending_;
  pending->store(false);
  run_->SetFrameHook([this, pending](const Frame& frame, const ArmMeasurement& m) {
    if (pending->exchange(true)) return;  // the view has not shown the last one yet
    const QImage image = ImageFromMat(frame.image);
    const int index = frame.index;
    QMetaObject::invokeMethod(
        this,
        [this, pending, image, index, m] {
          pending->store(false);
          emit frameReady(image, index, m);
        },
        Qt::QueuedConnection);
  });
  connect(run_.get(), &live::MimicRun::framePlanned, this,
          [this](int, bool, bool has_target, const robot::JointArray& target, const QString& hold) {
            emit planned(has_target, target, hold);
            emit latencyChanged(latencyText());
          });
  connect(run_.get(), &live::MimicRun::commandWritten, this,
          [this](const robot::JointArray& target, int) { emit commandWritten(target); });
  connect(run_.get(), &live::MimicRun::finished, this, [this](bool ok, const QString& message) {
    emit latencyChanged(latencyText());
    emit runningChanged(false);
    emit finished(ok, message);
  });
  const Status st = run_->Start(o);
  if (!st) {
    run_.reset();
    emit error(tr("Mimic live: %1").arg(QString::fromStdString(st.message())));
    return false;
  }
  applyHold();
  emit runningChanged(true);
  return true;
}

void MimicController::stop(const QString& reason) {
  if (running()) run_->Stop(reason.toStdString());
}

QString MimicController::latencyText() const {
  if (!run_) return tr("no run yet");
  const robot::LatencySummary s = run_->stream().Summary();
  if (s.frame_to_command.count == 0) {
    return tr("%1 frames analysed, no command yet (analysis %2 ms a frame)")
        .arg(s.frames)
        .arg(s.analysis.median_ms, 0, 'f', 1);
  }
  return tr("frame to command: median %1 ms, p95 %2 ms · %3 of %4 moves acknowledged · "
            "analysis %5 ms")
      .arg(s.frame_to_command.median_ms, 0, 'f', 1)
      .arg(s.frame_to_command.p95_ms, 0, 'f', 1)
      .arg(s.commands_acked)
      .arg(s.commands_sent)
      .arg(s.analysis.median_ms, 0, 'f', 1);
}

}  // namespace armmimic::gui
