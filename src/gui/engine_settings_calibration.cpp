// EngineSettingsPanel's calibration buttons for the tracking engines (lk, hybrid): the pose
// network's joints in the start frame (Auto-calibrate), and the joints the run calibrates itself
// from in the thesis protocol, shown before the run for the operator to accept or drag
// (Calibrate from standstill, Accept joints).
#include <QCheckBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QPushButton>

#include "armmimic/engines/pose.h"
#include "engine_settings_panel.h"

namespace armmimic::gui {

QWidget* EngineSettingsPanel::makeCalibrateRow() {
  auto* row = new QWidget;
  standstill_calibrate_ = new QPushButton(tr("Calibrate from standstill"), row);
  standstill_calibrate_->setObjectName("standstillCalibrate");
  standstill_calibrate_->setToolTip(
      tr("lk, hybrid with the background and arm-length image: the joints the run calibrates "
         "itself from, shown on the last standstill frame to accept or drag"));
  accept_estimate_ = new QPushButton(tr("Accept joints"), row);
  accept_estimate_->setObjectName("acceptEstimate");
  accept_estimate_->setToolTip(
      tr("Hide the estimated joints: the run calibrates itself as shown, or starts from the "
         "joints you dragged"));
  auto* l = new QHBoxLayout(row);
  l->setContentsMargins(0, 0, 0, 0);
  l->addWidget(standstill_calibrate_, 1);
  l->addWidget(accept_estimate_);
  connect(standstill_calibrate_, &QPushButton::clicked, this,
          &EngineSettingsPanel::standstillCalibrateRequested);
  connect(accept_estimate_, &QPushButton::clicked, this, [this] {
    setEstimateShown(false);
    emit estimateAccepted();
  });
  return row;
}

void EngineSettingsPanel::setEstimateShown(bool shown) {
  estimate_shown_ = shown;
  updateEnabled();
}

Status EngineSettingsPanel::autoCalibrate(const std::vector<std::string>& inputs) {
  if (inputs.empty()) return Status::Error("Auto-calibrate: open a video first");
  const AnalysisOptions o = options();
  PoseArm arm;
  PoseSide side = PoseSide::kAuto;
  const Status st =
      DetectArmJoints(inputs, o.start, PoseSide::kAuto, o.model_dir, o.engine.pose, &arm, &side);
  if (!st) return Status::Error(st.key(), "Auto-calibrate: " + st.message());

  setJoint(1, arm.elbow);
  setJoint(2, arm.wrist);
  setShoulder(arm.shoulder);
  return Status::Ok();
}

void EngineSettingsPanel::clearJoints() {
  setShoulder(std::nullopt);
  elbow_wrist_box_->setChecked(false);
}

}  // namespace armmimic::gui
