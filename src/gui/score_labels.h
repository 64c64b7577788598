// Where the pose overlay writes its keypoints' scores: no two labels overlap, nor a label a dot.
// The face's five keypoints and a bent arm's joints lie closer than a label is wide, and labels
// written at one fixed offset ran into each other ("0.40.511").
#pragma once

#include <optional>
#include <vector>

#include <QFontMetricsF>
#include <QPointF>
#include <QRectF>
#include <QString>

namespace armmimic::gui {

struct ScoreLabel {
  QString text;      // "0.87"
  QPointF baseline;  // where the text starts, on its baseline
  QRectF rect;       // the box it covers
};

// One entry per dot, in the dots' order: the best-scored keypoints are placed first, each at the
// first free spot beside its dot (right above, right below, left above, left below); nullopt
// when every spot is taken. `unit`: the overlay's scale (pixels per 240th of the image height).
std::vector<std::optional<ScoreLabel>> PlaceScoreLabels(const std::vector<QPointF>& dots,
                                                        const std::vector<double>& scores,
                                                        const QFontMetricsF& metrics, double unit);

}  // namespace armmimic::gui
