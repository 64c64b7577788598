// MainWindow's wiring of the tracking engines' calibration (lk, hybrid): Auto-calibrate fills the
// joints from the pose network; Calibrate from standstill shows the joints the run would
// calibrate itself from as handles on the last standstill frame, where a drag fills the joint
// fields (VideoView::jointPicked, as clicks do) and Accept hides them.
#include <memory>
#include <sstream>
#include <string>

#include "analysis_job.h"
#include "engine_settings_panel.h"
#include "log_view.h"
#include "main_window.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::gui {
namespace {

// What the estimate on the last standstill frame depends on (standstill_estimate.h): another
// value of any of these makes the handles shown out of date.
std::string EstimateInputs(const AnalysisOptions& o) {
  std::ostringstream s;
  s << static_cast<int>(o.engine.kind) << '|' << o.start << '|' << o.background_path << '|'
    << o.background_frames << '|' << o.arm_length_path << '|' << o.engine.lk.standstill_frames
    << '|' << o.engine.lk.body_threshold << '|' << static_cast<int>(o.engine.lk.side) << '|'
    << o.engine.lk.upper_fraction;
  if (o.roi) s << '|' << o.roi->x << ',' << o.roi->y << ',' << o.roi->width << ',' << o.roi->height;
  return s.str();
}

}  // namespace

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
  // The inputs the handles shown were estimated from.
  auto shown_for = std::make_shared<std::string>();
  connect(
      job_, &AnalysisJob::standstillReady, this, [this, shown_for](const StandstillJoints& joints) {
        settings_->clearJoints();  // accepting these joints leaves the run to its own calibration
        *shown_for = EstimateInputs(settings_->options());
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
  // Another engine, start frame, standstill or image: the handles shown are another run's.
  connect(settings_, &EngineSettingsPanel::changed, this, [this, shown_for] {
    if (view_->jointHandles().empty() || EstimateInputs(settings_->options()) == *shown_for) return;
    view_->clearJointHandles();
    settings_->setEstimateShown(false);
    log_->info(
        tr("The estimated joints were for other settings: calibrate from the standstill "
           "again to see the run's"));
  });
  // Another input: its standstill is another.
  connect(player_, &VideoPlayer::opened, this, [this] {
    view_->clearJointHandles();
    settings_->setEstimateShown(false);
  });
}

}  // namespace armmimic::gui
