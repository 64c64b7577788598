// The thesis overlay (appendix B, Fig. 4-3): frame count upper left, yaw middle right, upper-arm
// and forearm orientation lower right, centres of mass as circles, the segments, elbow and
// shoulder, and for the marker engine the markers and candidate boxes. Painted in image pixels,
// so the same code draws the view and the saved frame.
#pragma once

#include <QPainter>
#include <QSize>
#include <QString>

#include "armmimic/engines/measurement.h"

namespace armmimic::gui {

struct OverlayOptions {
  bool frame_count = true;
  bool yaw = true;
  bool orientation = true;
  bool centres = true;
  bool segments = true;
  bool elbow = true;
  bool shoulder = true;
  bool markers = true;   // marker centres and candidate boxes
  bool features = true;  // LK features
  bool contour = false;  // arm contour and hull
};

// The texts the overlay shows, so tests and the status bar read the same values.
struct OverlayTexts {
  QString frame;        // "frame 12 / 300"
  QString yaw;          // "yaw 23.4°" or "yaw —"
  QString orientation;  // "upper -90.0°  fore -45.0°"; for a marker view "bend 12.0°"
  QString state;        // "ok", "lost: <note>", "setup"
};

OverlayTexts MakeOverlayTexts(const ArmMeasurement* m, int frame_index, int frame_count);

// Paints over an image of `image_size` pixels (the painter maps image pixels). `m` may be null
// (no result for this frame): only the frame count is drawn.
void PaintOverlay(QPainter& painter, QSize image_size, const ArmMeasurement* m, int frame_index,
                  int frame_count, const OverlayOptions& options);

}  // namespace armmimic::gui
