#include "armmimic/engines/measurement.h"

namespace armmimic {

AngleRow ArmMeasurement::ToRow() const {
  AngleRow row;
  row.frame = frame;
  row.time_s = time_s;
  row.status = phase == MeasurementPhase::kOk ? RowStatus::kOk : RowStatus::kLost;
  row.file = file;
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
  }
  return row;
}

}  // namespace armmimic
