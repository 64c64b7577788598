// The thesis overlay (appendix B, Fig. 4-3): frame count upper left, yaw middle right, upper-arm
// and forearm orientation lower right, centres of mass as circles, the segments, elbow and
// shoulder, for the marker engine the markers, candidate boxes, the lower part's fitted cylinder
// (silhouette and axis) and the signed yaw, and for the pose engine the skeleton with each
// keypoint's score. With both arms measured (the pose engine's side both), each arm's segments
// and joints, and the texts of the arm picked (OverlayOptions::arm). Painted in image pixels, so
// the same code draws the view and the saved frame.
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
  bool markers = true;   // marker centres, candidate boxes and the fitted cylinder
  bool features = true;  // LK features
  bool contour = false;  // arm contour and hull
  bool skeleton = true;  // pose engine: the keypoints, bones and keypoint scores
  int arm = 0;  // with both arms measured: the arm whose angles the texts show (0 left, 1 right)
};

// The texts the overlay shows, so tests and the status bar read the same values.
struct OverlayTexts {
  QString frame;        // "frame 12 / 300"
  QString yaw;          // "yaw 23.4°", for the marker engine signed ("yaw -23.4°"), or "yaw —"
  QString orientation;  // "upper -90.0°  fore -45.0°"; for a marker view "bend 12.0°"
  QString state;        // "ok", "lost: <note>", "setup"
};

// `m`: the arm the texts are about (ArmMeasurement::Arm(OverlayOptions::arm)).
OverlayTexts MakeOverlayTexts(const ArmMeasurement* m, int frame_index, int frame_count);

// Paints over an image of `image_size` pixels (the painter maps image pixels). `m` may be null
// (no result for this frame): only the frame count is drawn. Shapes, then the texts at the
// image's corners: the saved frame.
void PaintOverlay(QPainter& painter, QSize image_size, const ArmMeasurement* m, int frame_index,
                  int frame_count, const OverlayOptions& options);

// The two halves of PaintOverlay, for a view that zooms and pans: the shapes in image pixels,
// and the texts at the corners of `area` (in the painter's units) with `unit` as the size of one
// image pixel at 320x240 (letters 8 units high), so they stay readable at any zoom.
void PaintOverlayShapes(QPainter& painter, QSize image_size, const ArmMeasurement* m,
                        const OverlayOptions& options);
void PaintOverlayTexts(QPainter& painter, const QRectF& area, double unit, const ArmMeasurement* m,
                       int frame_index, int frame_count, const OverlayOptions& options);
// One unit of the overlay for an image of `image_size`: 1 at 240 rows, more for taller frames.
double OverlayUnit(QSize image_size);

}  // namespace armmimic::gui
