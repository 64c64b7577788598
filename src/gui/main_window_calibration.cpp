// MainWindow's wiring of the tracking engines' calibration (lk, hybrid): Auto-calibrate fills the
// joints from the pose network; Calibrate from standstill shows the joints the run would
// calibrate itself from as handles on the last standstill frame, where a drag fills the joint
// fields (VideoView::jointPicked, as clicks do) and Accept hides them.
#include "analysis_job.h"
#include "engine_settings_panel.h"
#include "log_view.h"
#include "main_window.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::gui {

void MainWindow::wireCalibration() {
  auto inputs = [this] {
    std::vector<std::string> out;
    for (const QString& s : player_->inputs()) out.push_back(s.toStdString());
    return out;
  };
  connect(settings_, &EngineSettingsPanel::autoCalibrateRequested, this, [this, inputs] {
    const Status st = settings_->autoCalibrate(inputs());
    if (!st) {
      return log_->error(settings_->showError(QString::fromStdString(st.key()),
                                              QString::fromStdString(st.message())));
    }
    log_->info(tr("Auto-calibrated the arm's joints from the pose network"));
  });
  // The estimate reads the video on the analysis thread; its errors come as the analysis's do
  // (AnalysisJob::failed, worded at their field).
  connect(settings_, &EngineSettingsPanel::standstillCalibrateRequested, this, [this] {
    if (!player_->isOpen() || player_->isLive()) {
      return log_->error(
          tr("Calibrate from standstill: open a video first; a camera's "
             "standstill is calibrated by the run itself"));
    }
    AnalysisOptions o = settings_->options();
    o.inputs.clear();
    for (const QString& s : player_->inputs()) o.inputs.push_back(s.toStdString());
    job_->startStandstill(o);
  });
  connect(job_, &AnalysisJob::standstillReady, this, [this](const StandstillJoints& joints) {
    settings_->clearJoints();  // accepting these joints leaves the run to its own calibration
    auto at = [](const cv::Point2d& p) { return QPointF(p.x, p.y); };
    view_->setJointHandles(joints.frame,
                           {at(joints.shoulder_px), at(joints.elbow_px), at(joints.wrist_px)});
    settings_->setEstimateShown(true);
    player_->pause();
    player_->seek(joints.frame);
    log_->info(tr("Estimated joints on frame %1 (%2). Accept them, and the run calibrates "
                  "itself so; or drag a handle, and the joints shown become clicked joints")
                   .arg(joints.frame)
                   .arg(QString::fromStdString(joints.description)));
  });
  connect(settings_, &EngineSettingsPanel::estimateAccepted, this, [this] {
    view_->clearJointHandles();
    log_->info(settings_->options().shoulder_px
                   ? tr("Joints accepted: the run starts from the joints dragged")
                   : tr("Joints accepted: the run calibrates itself from the standstill"));
  });
  // Another input: its standstill is another.
  connect(player_, &VideoPlayer::opened, this, [this] {
    view_->clearJointHandles();
    settings_->setEstimateShown(false);
  });
}

}  // namespace armmimic::gui
