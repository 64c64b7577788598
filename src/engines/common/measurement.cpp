#include "armmimic/engines/measurement.h"

namespace armmimic {

std::vector<const ArmMeasurement*> ArmMeasurement::Arms() const {
  std::vector<const ArmMeasurement*> arms = {this};
  if (right_arm) arms.push_back(right_arm.get());
  return arms;
}

const ArmMeasurement& ArmMeasurement::Arm(std::size_t arm) const {
  return arm == 1 && right_arm ? *right_arm : *this;
}

AngleRow ArmMeasurement::ToRow() const {
  AngleRow row;
  row.frame = frame;
  row.time_s = time_s;
  row.status = phase == MeasurementPhase::kOk ? RowStatus::kOk : RowStatus::kLost;
  row.file = file;
  row.confidence = confidence;
  if (row.ok()) {
    row.upper_deg = upper_deg;
    row.fore_deg = fore_deg;
    row.yaw_deg = yaw_deg;
    row.bend_deg = bend_deg;
    row.yaw_signed_deg = yaw_signed_deg;
    row.upper_cx = upper_com_px.x;
    row.upper_cy = upper_com_px.y;
    row.fore_cx = fore_com_px.x;
    row.fore_cy = fore_com_px.y;
    row.upper_az_deg = upper_az_deg;
    row.upper_el_deg = upper_el_deg;
    row.fore_az_deg = fore_az_deg;
    row.fore_el_deg = fore_el_deg;
    row.elbow_deg = elbow_deg;
  }
  return row;
}

ArmMeasurement ArmMeasurement::FromRow(const AngleRow& row) {
  ArmMeasurement m;
  m.frame = row.frame;
  m.time_s = row.time_s;
  m.phase = row.ok() ? MeasurementPhase::kOk : MeasurementPhase::kLost;
  m.file = row.file;
  m.upper_deg = row.upper_deg;
  m.fore_deg = row.fore_deg;
  m.yaw_deg = row.yaw_deg;
  m.bend_deg = row.bend_deg;
  m.yaw_signed_deg = row.yaw_signed_deg;
  m.confidence = row.confidence;
  m.upper_com_px = {row.upper_cx, row.upper_cy};
  m.fore_com_px = {row.fore_cx, row.fore_cy};
  m.upper_az_deg = row.upper_az_deg;
  m.upper_el_deg = row.upper_el_deg;
  m.fore_az_deg = row.fore_az_deg;
  m.fore_el_deg = row.fore_el_deg;
  m.elbow_deg = row.elbow_deg;
  return m;
}

}  // namespace armmimic
