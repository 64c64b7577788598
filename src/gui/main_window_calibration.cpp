// MainWindow's wiring of the tracking engines' calibration (lk, hybrid): Auto-calibrate fills the
// joints from the pose network; Calibrate from standstill shows the joints the run would
// calibrate itself from as handles on the last standstill frame, where a drag fills the joint
// fields (VideoView::jointPicked, as clicks do) and Accept hides them.
#include <QApplication>

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
  auto report = [this](const Status& st) {
    log_->error(settings_->showError(QString::fromStdString(st.key()),
                                     QString::fromStdString(st.message())));
  };
  connect(settings_, &EngineSettingsPanel::autoCalibrateRequested, this, [this, inputs, report] {
    const Status st = settings_->autoCalibrate(inputs());
    if (!st) return report(st);
    log_->info(tr("Auto-calibrated the arm's joints from the pose network"));
  });
  connect(settings_, &EngineSettingsPanel::standstillCalibrateRequested, this,
          [this, inputs, report] {
            if (player_->isLive()) {  // its standstill has passed; the run takes the next one
              return log_->error(
                  tr("Calibrate: open a video; a camera's standstill is "
                     "calibrated by the run itself"));
            }
            StandstillJoints joints;
            QApplication::setOverrideCursor(Qt::WaitCursor);
            const Status st = settings_->estimateStandstill(inputs(), &joints);
            QApplication::restoreOverrideCursor();
            if (!st) return report(st);
            auto at = [](const cv::Point2d& p) { return QPointF(p.x, p.y); };
            view_->setJointHandles(
                joints.frame, {at(joints.shoulder_px), at(joints.elbow_px), at(joints.wrist_px)});
            settings_->setEstimateShown(true);
            player_->pause();
            player_->seek(joints.frame);
            log_->info(tr("Estimated joints on frame %1 (%2). Accept them, and the run calibrates "
                          "itself so; or drag a handle, and the joints shown are clicked joints")
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
